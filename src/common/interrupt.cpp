#include "common/interrupt.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string>

namespace systole {
namespace {

// The table of pending paths: plain char buffers, so a signal handler can remove them
// without allocating or locking.
constexpr int kMaxPending = 128;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kClaimed = 1, kReady = 2 };
// The handler reads slot states on whichever thread the signal lands (the frame loop's
// stages run on their own threads): only a lock-free atomic is safe there.
static_assert(std::atomic<int>::is_always_lock_free);
struct PendingSlot {
  std::atomic<int> state{kFree};
  bool folder = false;
  char path[kMaxPath] = {};
};
std::array<PendingSlot, kMaxPending> g_pending;

int register_pending(const std::filesystem::path& p, bool folder) {
  const std::string s = p.string();
  if (s.size() >= kMaxPath) return -1;
  for (int i = 0; i < kMaxPending; ++i) {
    int expected = kFree;
    if (g_pending[i].state.compare_exchange_strong(expected, kClaimed)) {
      g_pending[i].folder = folder;
      std::memcpy(g_pending[i].path, s.c_str(), s.size() + 1);
      g_pending[i].state.store(kReady);
      return i;
    }
  }
  return -1;
}

/// Unlinks the files of `path`, then removes it. A frame written meanwhile by another thread
/// makes rmdir fail: a few more passes catch it; whatever is still left is a dead writer's,
/// which the next run in that folder removes.
void remove_folder_signal_safe(const char* path) {
  for (int pass = 0; pass < 4; ++pass) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) return;
    alignas(dirent64) char buffer[8192];
    for (ssize_t n; (n = ::getdents64(fd, buffer, sizeof buffer)) > 0;) {
      for (ssize_t at = 0; at < n;) {
        const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
        const char* name = entry->d_name;
        const bool dots = name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'));
        if (!dots) ::unlinkat(fd, name, 0);
        at += entry->d_reclen;
      }
    }
    ::close(fd);
    if (::rmdir(path) == 0 || errno != ENOTEMPTY) return;
  }
}

// Commits under way (InterruptsWait), and the signal that came during one.
std::atomic<int> g_commits{0};
std::atomic<int> g_deferred_signal{0};

// The outputs written so far: text appended under a mutex; its length published last, so
// a handler reads only bytes already in place.
constexpr std::size_t kWrittenCapacity = 2048;
std::array<char, kWrittenCapacity> g_written;
std::atomic<std::size_t> g_written_size{0};
std::mutex g_written_mutex;

}  // namespace

int register_pending_file(const std::filesystem::path& file) { return register_pending(file, false); }

int register_pending_folder(const std::filesystem::path& folder) { return register_pending(folder, true); }

void unregister_pending(int slot) {
  if (slot >= 0) g_pending[static_cast<std::size_t>(slot)].state.store(kFree);
}

void remove_pending_outputs_signal_safe() {
  for (auto& slot : g_pending) {
    if (slot.state.load() != kReady) continue;
    if (slot.folder) {
      remove_folder_signal_safe(slot.path);
    } else {
      ::unlink(slot.path);
    }
  }
}

bool interrupt_deferred_signal_safe(int sig) {
  // Kept first, checked second: a commit that ends between the two has either seen the
  // signal (and raises it) or ended before the check (and this handler goes on).
  int none = 0;
  g_deferred_signal.compare_exchange_strong(none, sig);
  if (g_commits.load() > 0) return true;
  g_deferred_signal.store(0);
  return false;
}

InterruptsWait::InterruptsWait() { g_commits.fetch_add(1); }

InterruptsWait::~InterruptsWait() {
  if (g_commits.fetch_sub(1) != 1) return;
  if (const int sig = g_deferred_signal.exchange(0); sig != 0) std::raise(sig);
}

void note_output_written(const std::filesystem::path& output) {
  const std::lock_guard guard(g_written_mutex);
  std::size_t size = g_written_size.load();
  const std::string item = (size > 0 ? ", '" : "'") + output.string() + "'";
  constexpr std::string_view kMore = ", ...";
  if (size + item.size() + kMore.size() > kWrittenCapacity) {
    if (std::string_view(g_written.data(), size).ends_with(kMore)) return;
    std::memcpy(g_written.data() + size, kMore.data(), kMore.size());
    g_written_size.store(size + kMore.size());
    return;
  }
  std::memcpy(g_written.data() + size, item.data(), item.size());
  g_written_size.store(size + item.size());
}

std::string_view outputs_written_signal_safe() { return {g_written.data(), g_written_size.load()}; }

}  // namespace systole
