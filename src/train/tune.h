#pragma once
// Training and tuning of every organ with a target (the paper's first contribution):
// record the forces that make the body follow the target, fit each region's drive as a
// Fourier series, then tune the free region parameters with CMA-ES so the body, running
// free, matches the target.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "train/playback.h"

namespace systole::train {

struct TuneSettings {
  int budget = -1;            ///< Playbacks per organ; < 0: each target's `budget`.
  std::uint64_t seed = 1;     ///< Seeds the search (the scene's seed by default).
  int threads = 1;            ///< Candidates evaluated at once; the result is the same at any count.
  std::function<void(const std::string&)> log;  ///< Progress lines (one per generation); may be empty.
};

/// One tunable number of one region, searched in a box [lo, hi] (periodic ones wrap).
struct Parameter {
  enum class Kind { kAmplitude, kHarmonicAmplitude, kHarmonicPhase, kDelay, kLogStiffness };
  std::string name;  ///< "left_ventricle.harmonic2.phase"
  int region = 0;
  Kind kind = Kind::kAmplitude;
  int harmonic = 0;  ///< Index into the drive's harmonics.
  double lo = 0, hi = 1;
  bool periodic = false;
  double step = 0.1;  ///< Initial search step. Same unit as the value.
};

struct OrganTuning {
  std::string organ;
  std::vector<scene::Region> regions;   ///< Tuned (what TUNED.yaml writes).
  std::vector<scene::Region> fitted;    ///< Fitted from the recorded forces, untuned.
  std::vector<Parameter> parameters;    ///< What was free.
  std::vector<bool> drive_trained;      ///< Per region: its drive was fitted and tuned (else as written).
  PlaybackError written, before, after; ///< The scene's own drives, the untuned fit, the tuned drives.
  PlaybackError after_half_step;        ///< The tuned drives at half the scene's step: the step is converged when it matches `after`.
  PlaybackError floor;                  ///< The body tied to the target (train/coupling.h): the best it does.
  PlaybackError fitted_from_forces, fitted_from_lengths;  ///< The two fits; `before` is the closer.
  std::string start_from;               ///< "forces" or "lengths": the fit the search started from.
  bool kept_written = false;            ///< The search ended farther than the drives as written: `regions` are those.
  double coupling_N_per_m = 0;          ///< The target's coupling (what the floor was measured at). unit: N/m
  std::string transfer;                 ///< How the target was laid on the organ and what that lost (train/transfer.h); "" for its own mesh.
  std::vector<std::vector<double>> target_size;  ///< Per region, over the measured steps (Problem::target_size).
  double measure_start_s = 0, dt_s = 0, rate_hz = 0;
  double target_motion_m = 0;                ///< Problem::target_motion_m. unit: m
  double target_motion_pct_of_diagonal = 0;  ///< The same, % of the bounding diagonal.
  double mean_coupling_force_N = 0;
  int generations = 0, evaluations = 0;
  std::string stop_reason;
  double seconds = 0;                   ///< Wall time of fitting and tuning. unit: s
};

/// Whether the target's lock list keeps `param` ("amplitude", "shape", "delay", "stiffness")
/// of `region` as written.
bool is_locked(const scene::Target& target, const std::string& region, const std::string& param);

/// Fits and tunes one organ (which has a target).
OrganTuning tune_organ(const scene::Scene& scene, std::size_t organ_index, const TuneSettings& settings);

}  // namespace systole::train
