#pragma once
// A small tmpfs, for tests of a full disk. Mounting needs root and mount rights (CI runs
// the suite as root); where they are missing, `mounted` is false and the test skips with
// a message.

#include <sys/mount.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace systole::test {

/// A tmpfs of `size` ("1m", "200k") mounted at `dir` (made, and emptied, first) for the
/// life of the object.
struct SmallDisk {
  std::filesystem::path dir;
  bool mounted = false;
  SmallDisk(std::filesystem::path where, const std::string& size) : dir(std::move(where)) {
    ::umount2(dir.c_str(), MNT_DETACH);  // Left mounted by a run that crashed, if any.
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    mounted = ::geteuid() == 0 && ::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted) ::umount2(dir.c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;
};

inline constexpr const char* kNoSmallDisk =
    "cannot mount a small tmpfs here (needs root and mount rights): full disk not tested";

}  // namespace systole::test
