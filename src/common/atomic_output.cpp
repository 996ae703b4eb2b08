#include "common/atomic_output.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <system_error>

#include "common/error.h"

namespace systole {
namespace {

// Temporary paths live in a fixed table of plain char buffers so a signal handler can
// unlink them without allocating or locking.
constexpr int kMaxPending = 64;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kClaimed = 1, kReady = 2 };
// The handler reads slot states on whichever thread the signal lands (the frame loop's
// stages run on their own threads): only a lock-free atomic is safe there.
static_assert(std::atomic<int>::is_always_lock_free);
struct PendingSlot {
  std::atomic<int> state{kFree};
  char path[kMaxPath] = {};
};
std::array<PendingSlot, kMaxPending> g_pending;
std::atomic<unsigned> g_counter{0};

int register_pending(const std::filesystem::path& p) {
  const std::string s = p.string();
  if (s.size() >= kMaxPath) return -1;
  for (int i = 0; i < kMaxPending; ++i) {
    int expected = kFree;
    if (g_pending[i].state.compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(g_pending[i].path, s.c_str(), s.size() + 1);
      g_pending[i].state.store(kReady);
      return i;
    }
  }
  return -1;  // Table full: the destructor still cleans up; only a signal would miss it.
}

void unregister_pending(int slot) {
  if (slot >= 0) g_pending[slot].state.store(kFree);
}

}  // namespace

AtomicOutput::AtomicOutput(std::filesystem::path target) : target_(std::move(target)) {
  namespace fs = std::filesystem;
  if (target_.empty()) throw Error(ExitCode::kCannotCreate, "output path is empty");
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw Error(ExitCode::kCannotCreate,
                "cannot create '" + target_.string() + "': directory '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw Error(ExitCode::kCannotCreate,
                "cannot create '" + target_.string() + "': directory '" + dir.string() + "' is not writable");
  }
  if (fs::is_directory(target_, ec)) {
    throw Error(ExitCode::kCannotCreate, "cannot create '" + target_.string() + "': it is a directory");
  }
  const std::string name = "." + target_.stem().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                           std::to_string(g_counter.fetch_add(1)) + target_.extension().string();
  temp_ = dir / name;
  slot_ = register_pending(temp_);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  unregister_pending(slot_);
}

void AtomicOutput::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) {
    throw Error(ExitCode::kIoError, "cannot move '" + temp_.string() + "' to '" + target_.string() + "': " + ec.message());
  }
  committed_ = true;
}

void remove_pending_outputs_signal_safe() {
  for (auto& slot : g_pending) {
    if (slot.state.load() == kReady) ::unlink(slot.path);
  }
}

}  // namespace systole
