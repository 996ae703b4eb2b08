#include "common/atomic_output.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "common/error.h"
#include "common/interrupt.h"

namespace systole {
namespace fs = std::filesystem;
namespace {

std::atomic<unsigned> g_counter{0};

// The locks this process holds, and the folders it has swept. A sweep must not take a lock
// this process holds through another descriptor: flock would refuse it, but on NFS, where
// flock becomes a per-process byte-range lock, it would be granted and then released.
struct HeldLock {
  int fd = -1;
  int slot = -1;          // Entry in the signal-safe table of pending files.
  std::thread::id owner;  // The thread whose OutputLocks may join it.
  int claims = 0;         // Claims (OutputLocks taken by a run) holding it.
  bool writer = false;    // An AtomicOutput writes its target.
};
std::mutex g_mutex;
std::map<std::string, HeldLock> g_held_locks;
std::set<std::string> g_swept_dirs;

constexpr std::string_view kPartialTag = ".partial-";
constexpr std::string_view kLockSuffix = ".lock";

fs::path folder_of(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

/// An open descriptor holding the exclusive lock on `lock` (created if missing), or -1
/// when another open file holds it. Throws Error(kCannotCreate) if it cannot be opened.
int try_lock(const fs::path& lock) {
  // The releaser unlinks the file before unlocking it, so a lock taken on a file that is
  // no longer the one at `lock` guards nothing: open the new one and try again.
  for (int attempt = 0; attempt < 16; ++attempt) {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      throw Error(ExitCode::kCannotCreate, "cannot create the lock file '" + lock.string() + "': " + std::strerror(errno));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK || error == EINTR) return -1;
      throw Error(ExitCode::kCannotCreate, "cannot lock '" + lock.string() + "': " + std::strerror(error));
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(lock.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      return fd;
    }
    ::close(fd);
  }
  return -1;
}

/// Unlinks the lock file, then closes (and so unlocks) it: whoever opened it meanwhile
/// finds on locking that it holds a removed file and opens the new one.
void unlock(const fs::path& lock, int fd) {
  ::unlink(lock.c_str());
  ::close(fd);
}

std::string read_small_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return {};
  char buffer[256];
  const ssize_t n = ::read(fd, buffer, sizeof buffer - 1);
  ::close(fd);
  std::string text(buffer, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\0')) text.pop_back();
  return text;
}

/// "pid 123 on node7 since 2026-11-25 04:12:05 UTC": who holds a lock, for the message a
/// second writer gets.
std::string holder_text() {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "?");
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", &utc);
  return "pid " + std::to_string(::getpid()) + " on " + host + " since " + when + "\n";
}

/// The target file name a temporary or lock file in a folder belongs to, or "".
std::string target_of_leftover(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return {};
  if (const auto at = name.rfind(kPartialTag); at != std::string::npos && at > 1) return name.substr(1, at - 1);
  if (name.ends_with(kLockSuffix) && name.size() > 1 + kLockSuffix.size()) {
    return name.substr(1, name.size() - 1 - kLockSuffix.size());
  }
  return {};
}

}  // namespace

fs::path lock_path_of(const fs::path& target) {
  return folder_of(target) / ("." + target.filename().string() + std::string(kLockSuffix));
}

int sweep_stale_outputs(const fs::path& dir) {
  std::error_code ec;
  // Leftovers by the target they belong to: its temporaries, and whether a lock file is there.
  struct Leftovers {
    std::vector<fs::path> temporaries;
    bool lock_file = false;
  };
  std::map<std::string, Leftovers> by_target;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const std::string target = target_of_leftover(name);
    if (target.empty()) continue;
    if (name.find(kPartialTag) != std::string::npos) {
      by_target[target].temporaries.push_back(it->path());
    } else {
      by_target[target].lock_file = true;
    }
  }
  int removed = 0;
  for (const auto& [target, leftovers] : by_target) {
    const fs::path lock = lock_path_of(dir / target);
    {
      const std::lock_guard guard(g_mutex);
      if (g_held_locks.contains(lock.string())) continue;
    }
    int fd = -1;
    try {
      fd = try_lock(lock);
    } catch (const Error&) {
      continue;  // An unwritable folder: nothing of ours to clean.
    }
    if (fd < 0) continue;  // A live writer, here or on another node.
    for (const fs::path& temporary : leftovers.temporaries) removed += fs::remove(temporary, ec) ? 1 : 0;
    unlock(lock, fd);
    removed += leftovers.lock_file ? 1 : 0;
  }
  return removed;
}

OutputLock::OutputLock(fs::path target, bool as_writer) : lock_path_(lock_path_of(target)), writer_(as_writer) {
  const fs::path dir = folder_of(target);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw Error(ExitCode::kCannotCreate,
                "cannot create '" + target.string() + "': directory '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw Error(ExitCode::kCannotCreate,
                "cannot create '" + target.string() + "': directory '" + dir.string() + "' is not writable");
  }
  const std::string key = lock_path_.string();
  // A sweep by another process holds a free lock for a moment: a writer is given a second
  // to let it go before the target counts as taken.
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const std::lock_guard guard(g_mutex);
    if (const auto held = g_held_locks.find(key); held != g_held_locks.end()) {
      // This run's own claim, taken before its set-up: its writer joins it. A second writer,
      // or another thread (two jobs naming one file), is refused like another process.
      HeldLock& lock = held->second;
      if (lock.owner != std::this_thread::get_id() || (as_writer && lock.writer)) break;
      if (as_writer) {
        lock.writer = true;
      } else {
        ++lock.claims;
      }
      return;
    }
    const int fd = try_lock(lock_path_);
    if (fd < 0) continue;
    // Only the detail of a second writer's message depends on this write, so a failure is
    // not one of ours.
    const std::string holder = holder_text();
    [[maybe_unused]] const bool written = ::ftruncate(fd, 0) == 0 && ::pwrite(fd, holder.data(), holder.size(), 0) >= 0;
    g_held_locks[key] = HeldLock{fd, register_pending_file(lock_path_), std::this_thread::get_id(), as_writer ? 0 : 1, as_writer};
    return;
  }
  const std::string holder = read_small_file(lock_path_);
  throw Error(ExitCode::kBusy, "'" + target.string() + "' is being written by another run (" +
                                   (holder.empty() ? std::string("its lock is '") + key + "'" : holder) +
                                   "); wait for it to finish, or write to another file");
}

OutputLock::~OutputLock() {
  const std::lock_guard guard(g_mutex);
  const auto held = g_held_locks.find(lock_path_.string());
  if (held == g_held_locks.end()) return;
  HeldLock& lock = held->second;
  if (writer_) {
    lock.writer = false;
  } else {
    --lock.claims;
  }
  if (lock.claims > 0 || lock.writer) return;
  unregister_pending(lock.slot);
  unlock(lock_path_, lock.fd);
  g_held_locks.erase(held);
}

AtomicOutput::AtomicOutput(fs::path target) : target_(std::move(target)) {
  if (target_.empty()) throw Error(ExitCode::kCannotCreate, "output path is empty");
  std::error_code ec;
  if (fs::is_directory(target_, ec)) {
    throw Error(ExitCode::kCannotCreate, "cannot create '" + target_.string() + "': it is a directory");
  }
  lock_.emplace(target_, /*as_writer=*/true);
  const fs::path dir = folder_of(target_);
  bool first_in_folder = false;
  {
    const std::lock_guard guard(g_mutex);
    first_in_folder = g_swept_dirs.insert(fs::absolute(dir, ec).lexically_normal().string()).second;
  }
  if (first_in_folder) sweep_stale_outputs(dir);  // Our own lock is held, so it stays.

  const std::string name = "." + target_.filename().string() + std::string(kPartialTag) + std::to_string(::getpid()) +
                           "-" + std::to_string(g_counter.fetch_add(1)) + target_.extension().string();
  temp_ = dir / name;
  temp_slot_ = register_pending_file(temp_);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
  release();
}

void AtomicOutput::release() {
  unregister_pending(temp_slot_);
  temp_slot_ = -1;
  lock_.reset();
}

void AtomicOutput::commit() {
  {
    // A signal now waits for the rename and its note, so the handler's message is true.
    const InterruptsWait commit;
    std::error_code ec;
    fs::rename(temp_, target_, ec);
    if (ec) {
      throw Error(ExitCode::kIoError, "cannot move '" + temp_.string() + "' to '" + target_.string() + "': " + ec.message());
    }
    committed_ = true;
    note_output_written(target_);
    unregister_pending(temp_slot_);
    temp_slot_ = -1;
  }
  release();
}

void write_atomically(const fs::path& target, const std::function<void(std::ostream&)>& fill) {
  AtomicOutput output(target);
  {
    std::ofstream out(output.temp_path(), std::ios::binary);
    if (!out) throw Error(ExitCode::kCannotCreate, "cannot create '" + target.string() + "'");
    fill(out);
    out.close();
    if (!out) throw Error(ExitCode::kIoError, "cannot write '" + target.string() + "' (disk full?)");
  }
  output.commit();
}

void write_file_atomically(const fs::path& target, std::string_view bytes) {
  write_atomically(target, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

}  // namespace systole
