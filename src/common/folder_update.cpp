#include "common/folder_update.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/error.h"
#include "common/interrupt.h"

namespace systole {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kStagingTag = ".staging-";
constexpr std::string_view kJournalSuffix = ".journal";

std::atomic<unsigned> g_staging_counter{0};

fs::path parent_of(const fs::path& folder) { return folder.has_parent_path() ? folder.parent_path() : fs::path("."); }

/// What every staging folder of `folder` is named with first: `.<name>.staging-`.
std::string staging_prefix(const fs::path& folder) { return "." + folder.filename().string() + std::string(kStagingTag); }

/// True when `folder` is a mount point: a file renamed from beside it into it would cross
/// mounts (EXDEV). The mount id tells bind mounts of one file system apart too; without
/// it (old kernels) the device does.
bool is_mount_point(const fs::path& folder) {
  struct statx inside {}, beside {};
  const fs::path parent = parent_of(folder);
  if (::statx(AT_FDCWD, folder.c_str(), 0, STATX_MNT_ID, &inside) != 0 ||
      ::statx(AT_FDCWD, parent.c_str(), 0, STATX_MNT_ID, &beside) != 0) {
    return false;  // Not there yet: it will be made beside its parent's files.
  }
  if ((inside.stx_mask & beside.stx_mask & STATX_MNT_ID) != 0) return inside.stx_mnt_id != beside.stx_mnt_id;
  return inside.stx_dev_major != beside.stx_dev_major || inside.stx_dev_minor != beside.stx_dev_minor;
}

/// Where `folder`'s staging folders are: beside it, or inside it when it is a mount point.
/// Both are looked in for a dead run's, since the folder may have been mounted since.
std::vector<fs::path> staging_homes(const fs::path& folder) { return {parent_of(folder), folder}; }

/// The staging folder `journal` names, or "" when it names none: a journal cut short (a
/// run killed while writing it, when nothing had moved yet) ends without its newline.
fs::path staging_named_by(const fs::path& journal, const fs::path& folder) {
  const int fd = ::open(journal.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return {};
  char buffer[512];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  ::close(fd);
  if (n < 2 || buffer[n - 1] != '\n') return {};
  const std::string name(buffer, static_cast<std::size_t>(n - 1));
  if (!name.starts_with(staging_prefix(folder)) || name.find('/') != std::string::npos) return {};
  std::error_code ec;
  for (const fs::path& home : staging_homes(folder)) {
    if (fs::is_directory(home / name, ec)) return home / name;
  }
  return {};
}

/// Renames every file of `staging` over its namesake in `folder` (made if missing), in name
/// order (a sequence fills in frame order). Throws Error(kIoError) naming the file.
void move_staged_files(const fs::path& staging, const fs::path& folder,
                       const std::function<void(int moved)>& after_each_move) {
  std::error_code ec;
  std::vector<std::string> names;
  for (fs::directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec)) {
    names.push_back(it->path().filename().string());
  }
  if (ec) throw Error(ExitCode::kIoError, "cannot list '" + staging.string() + "': " + ec.message());
  std::sort(names.begin(), names.end());
  fs::create_directories(folder, ec);
  if (ec) throw Error(ExitCode::kIoError, "cannot create '" + folder.string() + "': " + ec.message());
  int moved = 0;
  for (const std::string& name : names) {
    if (::rename((staging / name).c_str(), (folder / name).c_str()) != 0) {
      throw Error(ExitCode::kIoError, "cannot move '" + (staging / name).string() + "' to '" + (folder / name).string() +
                                          "': " + std::strerror(errno));
    }
    if (after_each_move) after_each_move(++moved);
  }
}

/// Finishes the update of `folder` that a killed run had committed to (its journal is
/// there), then removes every staging folder dead runs left. The caller holds the lock.
void finish_killed_updates(const fs::path& folder) {
  const fs::path journal = journal_path_of(folder);
  std::error_code ec;
  if (fs::exists(fs::symlink_status(journal, ec))) {
    if (const fs::path staging = staging_named_by(journal, folder); !staging.empty()) {
      try {
        move_staged_files(staging, folder, nullptr);
      } catch (const Error& e) {
        throw Error(ExitCode::kIoError, "cannot finish the update of '" + folder.string() +
                                            "' that a killed run began (its journal: '" + journal.string() +
                                            "'): " + e.what());
      }
    }
    fs::remove(journal, ec);
  }
  const std::string prefix = staging_prefix(folder);
  for (const fs::path& home : staging_homes(folder)) {
    for (fs::directory_iterator it(home, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->path().filename().string().starts_with(prefix)) {
        std::error_code ignored;  // Housekeeping: what cannot go now goes next time.
        fs::remove_all(it->path(), ignored);
      }
    }
    ec.clear();
  }
}

/// `given` as update_folder_of() names it, with its parents made.
fs::path prepared_folder(const fs::path& given) {
  const fs::path folder = update_folder_of(given);
  std::error_code ec;
  if (folder.has_parent_path()) fs::create_directories(folder.parent_path(), ec);
  if (ec) throw Error(ExitCode::kCannotCreate, "cannot create '" + given.string() + "': " + ec.message());
  return folder;
}

}  // namespace

fs::path update_folder_of(fs::path dir) {
  // "frames/" and "frames//": the folder is the last named part.
  for (int i = 0; i < 8 && !dir.has_filename() && dir.has_relative_path(); ++i) dir = dir.parent_path();
  if (dir.filename() == "." || dir.filename() == "..") {
    dir = fs::absolute(dir).lexically_normal();
    if (!dir.has_filename()) dir = dir.parent_path();
  }
  if (!dir.has_filename() || !dir.has_relative_path()) {
    throw Error(ExitCode::kCannotCreate, "cannot write into '" + dir.string() + "': name a folder to hold the files");
  }
  std::error_code ec;
  if (fs::is_symlink(dir, ec)) {
    if (const fs::path real = fs::canonical(dir, ec); !ec) return real;
  }
  return dir;
}

fs::path journal_path_of(const fs::path& folder) {
  return parent_of(folder) / ("." + folder.filename().string() + std::string(kJournalSuffix));
}

FolderUpdate::FolderUpdate(const fs::path& folder) : folder_(prepared_folder(folder)), lock_(folder_, /*as_writer=*/true) {
  finish_killed_updates(folder_);
  std::error_code ec;
  const fs::file_status status = fs::status(folder_, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw Error(ExitCode::kCannotCreate, "cannot write into the folder '" + folder_.string() + "': a file has that name");
  }
  if (fs::is_directory(status) && ::access(folder_.c_str(), W_OK) != 0) {
    throw Error(ExitCode::kCannotCreate, "cannot write into the folder '" + folder_.string() + "': it is not writable");
  }
  const fs::path home = fs::is_directory(status) && is_mount_point(folder_) ? folder_ : parent_of(folder_);
  staging_ = home / (staging_prefix(folder_) + std::to_string(::getpid()) + "-" + std::to_string(g_staging_counter.fetch_add(1)));
  if (::mkdir(staging_.c_str(), 0777) != 0) {
    throw Error(ExitCode::kCannotCreate, "cannot write into the folder '" + folder_.string() + "' (its staging folder '" +
                                             staging_.string() + "'): " + std::strerror(errno));
  }
  staging_slot_ = register_pending_folder(staging_);
}

FolderUpdate::~FolderUpdate() {
  unregister_pending(staging_slot_);
  if (committed_ || decided_) return;  // Decided: the journal promises the staged files to the folder.
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void FolderUpdate::write_journal() const {
  const fs::path journal = journal_path_of(folder_);
  const std::string text = staging_.filename().string() + "\n";
  const int fd = ::open(journal.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  bool written = fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const int error = errno;
  if (fd >= 0) written = ::close(fd) == 0 && written;
  if (!written) {
    ::unlink(journal.c_str());
    throw Error(ExitCode::kIoError, "cannot write the journal '" + journal.string() + "' to update '" +
                                        folder_.string() + "': " + std::strerror(error));
  }
}

void FolderUpdate::commit(const std::function<void(int moved)>& after_each_move) {
  if (committed_ || decided_) throw Error(ExitCode::kInternal, "'" + folder_.string() + "' committed twice");
  // SIGINT and SIGTERM now wait until the folder is whole again (common/interrupt.h).
  const InterruptsWait commit;
  std::error_code ec;
  if (!fs::exists(folder_, ec)) {
    // A new folder appears whole: one rename. (Made by someone meanwhile: moved into below.)
    if (::rename(staging_.c_str(), folder_.c_str()) == 0) {
      unregister_pending(staging_slot_);
      staging_slot_ = -1;
      committed_ = true;
      note_output_written(folder_);
      return;
    }
  }
  // A file over a folder of the same name would fail half-way: refuse before anything moves.
  for (fs::directory_iterator it(staging_, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path there = folder_ / it->path().filename();
    std::error_code absent;
    if (fs::is_directory(fs::symlink_status(there, absent))) {
      throw Error(ExitCode::kCannotCreate, "cannot write '" + there.string() + "': a folder has that name");
    }
  }
  // From the journal on, the staged files belong to the folder: neither the signal
  // handler nor the destructor may remove them.
  unregister_pending(staging_slot_);
  staging_slot_ = -1;
  write_journal();
  decided_ = true;
  try {
    move_staged_files(staging_, folder_, after_each_move);
  } catch (const Error& e) {
    throw Error(ExitCode::kIoError, std::string(e.what()) + "; the next run writing '" + folder_.string() +
                                        "' finishes the update (its journal: '" + journal_path_of(folder_).string() + "')");
  }
  fs::remove(staging_, ec);
  fs::remove(journal_path_of(folder_), ec);
  committed_ = true;
  note_output_written(folder_);
}

}  // namespace systole
