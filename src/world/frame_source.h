#pragma once
// One run of a scene's simulation for every consumer: the frame source builds the world,
// steps it (or replays frames recorded earlier: a bake, or frames it simulated ahead), and
// calls its listeners after every solver step and at every clip frame. The render, the
// soundtrack, the physiology, the motion check, the accuracy study, export's recorder and
// the bake writer are listeners on one source, so a clip's simulation runs once, as Jolt's
// contact listeners and MuJoCo's callbacks hook into one step.
//
// Inputs:  a validated scene; optionally a bake of it (replay_bake).
// Outputs: the render-mesh positions of each clip frame (positions), hooks' calls.
// See also: world/world.h (the world and its step), world/bake.h (the bake format).

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.h"
#include "sim/model.h"
#include "sim/state.h"
#include "world/bake.h"
#include "world/world.h"

namespace systole::world {

/// Called after every solver step of every stepped organ, with the organ's index; its
/// state.time_s is the step's end. For signals that need the simulation's own resolution
/// (heart sounds, valve timing, an ECG at its own rate). Never called on replayed frames.
using StepHook = std::function<void(int organ, const OrganBody& body)>;

/// Called once for every clip frame the source reaches, in order, frame 0 included, also for
/// frames nobody renders (a trace of a simulated signal needs them all). During the call,
/// FrameSource::positions gives that frame's positions.
using FrameHook = std::function<void(int frame)>;

class FrameSource {
 public:
  /// Builds every organ's body (build_world). Throws what build_world throws.
  explicit FrameSource(const scene::Scene& scene);
  // The world's step dispatch points at this source: it stays where it was built.
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  /// The world as built; its bodies' states are the simulation's (not a replay's).
  World& world() { return world_; }
  const World& world() const { return world_; }

  /// Listeners; add them before the first advance. Hooks run in the order they were added.
  void on_step(StepHook hook) { step_hooks_.push_back(std::move(hook)); }
  void on_frame(FrameHook hook) { frame_hooks_.push_back(std::move(hook)); }

  /// Frames come from `file` (a bake of `scene`, checked against the world) instead of the
  /// simulation; step hooks are never called. Throws what BakeReader throws.
  void replay_bake(const std::filesystem::path& file, const scene::Scene& scene);

  /// Simulates now through clip frame `last` (step and frame hooks called as usual) and keeps
  /// the positions of the frames `keep` names; later advances replay them. For consumers that
  /// need the whole run before the first frame is used (a soundtrack muxed with the video).
  /// Memory: 24 bytes per render vertex per kept frame.
  void simulate_ahead(int last, const std::vector<int>& keep);

  /// Stops the next advance between two frames with Error(kInterrupted) once `*cancel` is
  /// true (a preview that re-simulates on every edit); nullptr: never.
  void set_cancel(const std::atomic<bool>* cancel) { cancel_ = cancel; }

  /// Brings the source to clip frame `frame` (frames only move forward), stepping through
  /// every frame in between (world::advance_to_frame's checks and errors) or replaying.
  void advance_to(int frame);

  /// Whether frames come from a bake (replay_bake): no step hook is ever called.
  bool replays_bake() const { return bake_.has_value(); }

  /// The clip frame the source is at; -1 before the first advance.
  int frame() const { return frame_; }

  /// Organ `organ`'s render-mesh positions at the current frame. unit: m
  void positions(int organ, Eigen::Matrix3Xd& out);

  /// Every organ's positions at the current frame, one after another in organ order. unit: m
  void stacked_positions(Eigen::Matrix3Xd& out);

  /// Solver steps taken by all organs together (a coupled step counts once per organ).
  long long steps_taken() const { return steps_taken_; }

 private:
  void reach(int frame);  ///< Moves the source's frame to `frame` (one past the current).
  void check_cancel() const;

  World world_;
  std::vector<StepHook> step_hooks_;
  std::vector<FrameHook> frame_hooks_;
  std::optional<BakeReader> bake_;
  /// simulate_ahead's frames: kept_[k] holds frame kept_frames_[k]'s organs.
  std::vector<int> kept_frames_;
  std::vector<std::vector<Eigen::Matrix3Xd>> kept_;
  bool replaying_kept_ = false;
  const std::atomic<bool>* cancel_ = nullptr;
  int frame_ = -1;
  long long steps_taken_ = 0;
  std::vector<Eigen::Matrix3Xd> organ_scratch_;
};

/// The organs' positions one after another, in order, as one matrix. unit: m
void stack_positions(const std::vector<Eigen::Matrix3Xd>& organs, Eigen::Matrix3Xd& out);

/// One organ's body played alone from rest, step by step, with no world around it: training's
/// many short playbacks of candidate models (a fresh State each, nothing rebuilt), optionally
/// coupled to a target by attachments (sim/solvers/step.h).
class BodyPlayback {
 public:
  BodyPlayback(const sim::Model& model, double dt_s, const sim::Attachments* coupling = nullptr);
  /// Takes `steps` solver steps, calling `after_step(k)` after the k-th of them (0-based).
  void run(int steps, const std::function<void(int k)>& after_step = {});
  const sim::State& state() const { return state_; }
  sim::State& state() { return state_; }

 private:
  const sim::Model& model_;
  double dt_s_;
  const sim::Attachments* coupling_;
  sim::State state_;
};

}  // namespace systole::world
