#pragma once
// A training problem - one organ, its body and its target on a fixed time grid - and the
// error of the body running free (no coupling) against the target.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "sim/model.h"
#include "sim/reduced.h"
#include "sim/state.h"
#include "train/target.h"
#include "world/valves.h"

namespace systole::train {

struct Problem {
  std::string organ;
  sim::Model model;           ///< The organ's body as the scene builds it, without interactions.
  /// How the organ's render surface follows the body (a lattice's or a myocardium's); empty:
  /// the surface is the particles. The target moves the surface, and every error is
  /// measured on it: what the video shows, whatever body carries it.
  sim::Embedding embedding;
  Eigen::Matrix3Xd surface_rest;  ///< The render surface at rest. unit: m
  std::vector<int> surface_region;  ///< Per surface vertex: its region, -1 none.
  double dt_s = 0;            ///< The scene's step. unit: s
  double rate_hz = 0;         ///< The target's rate. unit: Hz
  int settle_steps = 0;       ///< Steps before the error is measured.
  int measure_steps = 0;      ///< Steps over which it is measured.
  TargetMotion target;
  std::vector<Eigen::Matrix3Xd> target_at_step;  ///< Target surface at each measured step. unit: m
  std::vector<double> target_volume_m3;          ///< Enclosed volume of the target at each measured step. unit: m^3
  /// Per region and measured step: the target's region size (RMS distance of its vertices
  /// from their centroid) relative to rest. unit: 1
  std::vector<std::vector<double>> target_size;
  /// The target's RMS motion about its mean shape over the measured steps (sim/motion_error.h):
  /// what every error is a share of. Per region the same over the region's vertices. unit: m
  double target_motion_m = 0;
  std::vector<double> target_region_motion_m;
  /// An anatomical heart's valves, closed (world/valves.h): the measured surface opens them
  /// as the scene's does, by the blood's phases or the flow; empty: no valves.
  world::ValveMotion valves;

  double measure_start_s() const { return settle_steps * dt_s; }
};

/// Builds the problem of the scene's organ `organ_index` (which must have a target): the
/// scene's body, step and solver, interactions left out (tuning fits the undisturbed rhythm).
Problem make_problem(const scene::Scene& scene, std::size_t organ_index);

/// Per region: the region's size (RMS distance of its surface vertices from their centroid)
/// relative to rest, for the render surface at `surface`. unit: 1
std::vector<double> region_sizes(const Problem& problem, const Eigen::Matrix3Xd& surface);

/// The render surface of body positions x. unit: m
void surface_of(const Problem& problem, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& surface);

struct RegionError {
  double rms_pct_of_motion = 0;  ///< RMS vertex error of the region, % of the region's target motion (NaN: the target keeps it still).
  double phase_deg = 0;          ///< Phase of the region size's first harmonic, played minus target. unit: deg
};

/// How far a playback is from the target. The main figure is a share of the target's motion
/// (a motionless organ in the target's mean shape scores 100 %); the diagonal-relative ones
/// are kept beside it, and the search minimizes rms_pct_of_diagonal - a fixed multiple of the
/// main figure for one target, so the same optimum, with the tuner's tolerances unchanged.
struct PlaybackError {
  double rms_pct_of_motion = 0;    ///< RMS vertex error over vertices and time, % of the target's RMS motion.
  double rms_pct_of_diagonal = 0;  ///< The same error, % of the bounding diagonal.
  double max_pct_of_diagonal = 0;  ///< Largest vertex error at any time, % of the bounding diagonal.
  double volume_percent = 0;       ///< RMS enclosed-volume error, % of the target's mean volume.
  /// The part of the RMS error that is a constant offset: each vertex's mean error over the
  /// measured steps, RMS over vertices, % of the target's motion. What is left,
  /// sqrt(rms^2 - offset^2), is the error of the motion about the mean shape. unit: %
  double mean_offset_pct_of_motion = 0;
  std::vector<RegionError> regions;
  std::vector<std::vector<double>> size;  ///< Per region and measured step, as Problem::target_size.
  bool diverged = false;      ///< The body blew up: every error is then infinite.
};

/// Sums a run's errors against the target, measured step by step on the render surface:
/// a free playback's, or the coupled recording's (the floor: the body tied to the target).
class ErrorMeter {
 public:
  /// How the measured surface's valves open: as the scene opens them (by the blood's phases
  /// or the flow), or as the target's do (the coupled recording, the floor: its leaflets
  /// are tied to the target's as its body is, and its solver, XPBD, holds no blood to open
  /// them by).
  enum class Valves { kAsTheScene, kAsTheTarget };
  explicit ErrorMeter(const Problem& problem, Valves valves = Valves::kAsTheScene);
  /// Follows the body at `state` without measuring it (the last settling step): the valves
  /// open by the flow since the step before, so they need the step before the first measured.
  void watch(const sim::State& state);
  /// Adds measured step k (0-based) with the body at `state`.
  void add(int k, const sim::State& state);
  /// The figures so far; every error infinite when `diverged` or a position was not finite.
  PlaybackError result(bool diverged = false) const;

 private:
  /// The render surface of `state` into surface_, valves opened as `valves_cue_` says;
  /// `target`: the target now (null while settling).
  void take_surface(const sim::State& state, const Eigen::Matrix3Xd* target);

  const Problem& problem_;
  world::ValveMotion valves_;  ///< This run's valves (their openings follow the run).
  Valves valves_cue_;
  Eigen::Matrix3Xd surface_;
  PlaybackError error_;  ///< The sizes, per region and step.
  Eigen::Matrix3Xd error_sum_;  ///< Per surface vertex: its error summed over the measured steps. unit: m
  std::vector<double> region_sq_;
  std::vector<int> region_count_;
  double sq_ = 0, max_sq_ = 0, volume_sq_ = 0, mean_volume_ = 0;
};

/// Runs `model` (a copy of problem.model with other drives) free from rest and measures it
/// against the target after the settling steps.
PlaybackError play(const Problem& problem, const sim::Model& model);

/// The base model with the scene regions' drives and stiffness scales (sim::with_regions).
sim::Model with_regions(const sim::Model& base, const std::vector<scene::Region>& regions);

/// Phase of the first harmonic at `rate_hz` of samples taken every dt from t0. unit: rad
double first_harmonic_phase(const std::vector<double>& samples, double t0_s, double dt_s, double rate_hz);

}  // namespace systole::train
