#include "world/frame_source.h"

#include <algorithm>
#include <string>

#include "common/error.h"
#include "common/warning.h"
#include "sim/solvers/step.h"

namespace systole::world {

FrameSource::FrameSource(const scene::Scene& scene) : world_(build_world(scene)) {
  if (!scene::anything_can_move(scene)) {
    warn(scene.path + ": nothing in this scene can move: no region has a drive or a volume drive with an amplitude, "
         "no pinned region has a motion, and there is no poke, grab or gravity; every frame shows the organ at rest");
  }
  // The one dispatch point of the world's steps: count them, then tell every listener.
  world_.after_step = [this](int organ, const OrganBody& body) {
    ++steps_taken_;
    for (const StepHook& hook : step_hooks_) hook(organ, body);
  };
}

void FrameSource::replay_bake(const std::filesystem::path& file, const scene::Scene& scene) {
  bake_.emplace(file).check_matches(scene, world_);
}

void FrameSource::simulate_ahead(int last, const std::vector<int>& keep) {
  if (bake_ || replaying_kept_) throw Error(ExitCode::kInternal, "simulate_ahead: the source already replays");
  kept_frames_ = keep;
  std::sort(kept_frames_.begin(), kept_frames_.end());
  kept_.clear();
  kept_.reserve(kept_frames_.size());
  for (int f = frame_ + 1; f <= last; ++f) {
    reach(f);
    if (!std::binary_search(kept_frames_.begin(), kept_frames_.end(), f)) continue;
    kept_.emplace_back(world_.organs.size());
    for (std::size_t o = 0; o < world_.organs.size(); ++o) render_positions(world_.organs[o], kept_.back()[o]);
  }
  // Frames kept past the simulated ones (or before where the source already was) cannot be
  // replayed: keep only those that were stored.
  kept_frames_.erase(std::remove_if(kept_frames_.begin(), kept_frames_.end(), [&](int f) { return f > last || f < 0; }),
                     kept_frames_.end());
  replaying_kept_ = true;
  frame_ = -1;  // The replay starts over; its frames' hooks were called while simulating.
}

void FrameSource::advance_to(int frame) {
  for (int f = frame_ + 1; f <= frame; ++f) reach(f);
}

void FrameSource::reach(int frame) {
  check_cancel();
  frame_ = frame;
  if (replaying_kept_) return;
  if (!bake_) advance_to_frame(world_, frame);
  for (const FrameHook& hook : frame_hooks_) hook(frame);
}

void FrameSource::check_cancel() const {
  if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed)) {
    throw Error(ExitCode::kInterrupted, "the simulation was cancelled at frame " + std::to_string(frame_ + 1));
  }
}

void FrameSource::positions(int organ, Eigen::Matrix3Xd& out) {
  if (bake_) {
    bake_->read(frame_, organ, out);
  } else if (replaying_kept_) {
    const auto it = std::lower_bound(kept_frames_.begin(), kept_frames_.end(), frame_);
    if (it == kept_frames_.end() || *it != frame_) {
      throw Error(ExitCode::kInternal, "frame " + std::to_string(frame_) + " was not kept by simulate_ahead");
    }
    out = kept_[static_cast<std::size_t>(it - kept_frames_.begin())][static_cast<std::size_t>(organ)];
  } else {
    render_positions(world_.organs[static_cast<std::size_t>(organ)], out);
  }
}

void FrameSource::stacked_positions(Eigen::Matrix3Xd& out) {
  organ_scratch_.resize(world_.organs.size());
  for (std::size_t o = 0; o < world_.organs.size(); ++o) positions(static_cast<int>(o), organ_scratch_[o]);
  stack_positions(organ_scratch_, out);
}

void stack_positions(const std::vector<Eigen::Matrix3Xd>& organs, Eigen::Matrix3Xd& out) {
  Eigen::Index total = 0;
  for (const auto& p : organs) total += p.cols();
  out.resize(3, total);
  Eigen::Index at = 0;
  for (const auto& p : organs) {
    out.middleCols(at, p.cols()) = p;
    at += p.cols();
  }
}

BodyPlayback::BodyPlayback(const sim::Model& model, double dt_s, const sim::Attachments* coupling)
    : model_(model), dt_s_(dt_s), coupling_(coupling), state_(sim::initial_state(model)) {}

void BodyPlayback::run(int steps, const std::function<void(int k)>& after_step) {
  for (int k = 0; k < steps; ++k) {
    sim::step(model_, state_, dt_s_, coupling_);
    if (after_step) after_step(k);
  }
}

}  // namespace systole::world
