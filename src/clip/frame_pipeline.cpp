#include "clip/frame_pipeline.h"

#include <array>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace systole::clip {
namespace {

constexpr int kStages = 3;

/// How far each stage got, and the first failure.
class Progression {
 public:
  explicit Progression(int depth) : depth_(depth) {}

  /// Waits until stage `s` may take frame `index`: the stage before finished it, and the
  /// stage after finished frame index - depth (so the slot `s` writes is free). False when
  /// another stage failed.
  bool wait_turn(int s, int index) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] {
      return failed_ || ((s == 0 || done_[s - 1] > index) && (s == kStages - 1 || done_[s + 1] > index - depth_));
    });
    return !failed_;
  }

  void finished(int s) {
    {
      std::lock_guard lock(mutex_);
      ++done_[s];
    }
    changed_.notify_all();
  }

  void fail(std::exception_ptr error) {
    {
      std::lock_guard lock(mutex_);
      if (!failed_) error_ = error;
      failed_ = true;
    }
    changed_.notify_all();
  }

  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  int depth_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::array<int, kStages> done_{};
  bool failed_ = false;
  std::exception_ptr error_;
};

}  // namespace

void run_frame_pipeline(int count, int depth, bool overlap, const PipelineStages& stages) {
  const std::array<const std::function<void(int, int)>*, kStages> stage = {&stages.produce, &stages.render,
                                                                           &stages.consume};
  if (!overlap) {
    for (int i = 0; i < count; ++i) {
      for (const auto* run : stage) (*run)(i, i % depth);
    }
    return;
  }
  Progression progression(depth);
  const auto run_stage = [&](int s) {
    try {
      for (int i = 0; i < count && progression.wait_turn(s, i); ++i) {
        (*stage[s])(i, i % depth);
        progression.finished(s);
      }
    } catch (...) {
      progression.fail(std::current_exception());
    }
  };
  {
    std::jthread producer(run_stage, 0);
    std::jthread consumer(run_stage, 2);
    run_stage(1);
  }  // Joined here.
  progression.rethrow();
}

}  // namespace systole::clip
