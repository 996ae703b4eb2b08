#pragma once
// Speed versus error (`systole bench`): the scene's organs run over a grid of solver x
// step x model configurations and are compared with a reference run that bench first
// proves converged: it runs the reference again at half the step (refining it when that
// moves it by more than 1 % of the motion) and asks a second, independent solver. Errors
// are a share of the reference's motion about its mean shape (a motionless organ scores
// 100 %, sim/motion_error.h), measured on the render mesh, so full and reduced models are
// judged by what the viewer sees; each periodically driven region's beat is compared too.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plot/plot.h"
#include "scene/scene.h"

namespace systole::study {

struct BenchConfig {
  scene::SolverMethod method = scene::SolverMethod::kProjective;
  double dt_s = 1.0 / 60.0;  ///< 0: the longest stable step (solver.dt: auto). unit: s
  int substeps = 1;          ///< Substeps per step; auto steps choose their own unless `refine` > 1.
  int lattice = 0;           ///< body.lattice: 0 full model, else voxels along the longest side.
  int iterations = 2;        ///< Projective: local/global iterations per substep.
  int refine = 1;            ///< Auto steps: the substeps they choose, times this (a halved reference).

  std::string label() const;  ///< "projective 1/60 s it2 full", "xpbd 1/240 s x4 lattice 8", "explicit auto x2".
  /// The same run at half the step: dt halved, or for an auto step twice its substeps.
  BenchConfig halved() const;
};

/// One periodically driven region's beat against the reference's.
struct RegionBeat {
  std::string name;               ///< "heart.left_atrium"
  double amplitude_error_pct = 0; ///< Of its radial excursion's fundamental at the drive's rate. unit: %
  double phase_lag_ms = 0;        ///< How much later than the reference's it peaks. unit: ms
  double peak_to_peak_error_pct = 0;  ///< unit: %
};

struct BenchResult {
  std::string label;              ///< The config's label, or what the row is ("frozen mean shape").
  BenchConfig config;
  std::string diverged;           ///< Why the run blew up; empty: it finished.
  double dt_s = 0;                ///< The step used (after rounding to the sample period). unit: s
  int substeps = 0;               ///< Substeps used.
  int particles = 0, springs = 0;
  double rms_pct_of_motion = 0;   ///< RMS vertex error over the compared samples, % of the reference's RMS motion.
  double rms_pct_of_diagonal = 0; ///< The same error, % of the rest bounding diagonal (secondary).
  double volume_error_pct = 0;    ///< RMS of (V - V_ref) / V_ref over the samples. unit: %
  std::vector<RegionBeat> regions;  ///< Every periodically driven region; empty when none is.
  double cost_ms_per_s = 0;       ///< Wall time per simulated second on one thread. unit: ms/s
  bool pareto = false;            ///< No other grid run is both cheaper and more accurate.

  double realtime_factor() const { return cost_ms_per_s > 0 ? 1000.0 / cost_ms_per_s : 0; }
  /// The region with the largest |amplitude error| and the largest |phase lag| (null: none).
  const RegionBeat* worst_amplitude() const;
  const RegionBeat* worst_phase() const;
};

/// What a reference run must satisfy to be used: halving its step moves it by at most this
/// share of the motion. unit: %
inline constexpr double kReferenceTolerancePct = 1.0;

struct BenchOptions {
  double duration_s = 0;        ///< Simulated time compared; 0: whole beats covering 2 s (bench_duration_s). unit: s
  double settle_s = -1;         ///< Simulated first and not compared; < 0: one beat of the first drive. unit: s
  double sample_hz = 60;        ///< How often positions are compared; steps are at most this long. unit: Hz
  BenchConfig reference{scene::SolverMethod::kProjective, 1.0 / 960.0, 1, 0, 2, 1};
  int max_refinements = 3;      ///< Halvings of the reference before bench refuses.
  /// The second solver that must reach the reference's motion; none: not asked.
  std::optional<BenchConfig> check = BenchConfig{scene::SolverMethod::kExplicit, 0, 1, 0, 2, 1};
  std::vector<BenchConfig> grid;  ///< Empty: default_grid().
};

struct BenchReport {
  std::string scene;
  double diagonal_m = 0;          ///< Bounding diagonal of the render meshes at rest. unit: m
  double motion_m = 0;            ///< The reference's RMS motion about its mean shape. unit: m
  BenchConfig reference;          ///< After any refinement.
  int refinements = 0;            ///< How many times the reference was halved to converge.
  BenchResult frozen;             ///< The reference's mean shape held still: 100 % by definition.
  BenchResult self_check;         ///< The reference at half its step, against the reference.
  std::optional<BenchResult> second_solver;  ///< options.check against the reference.
  double reference_cost_ms_per_s = 0;  ///< unit: ms/s
  BenchOptions options;
  std::vector<BenchResult> results;
};

/// The grid `systole bench` runs when not narrowed: projective dynamics at frame-rate and
/// finer steps with 1 to 3 iterations, on the full model and on lattices; XPBD at a few
/// substep counts; the implicit solver. The reference's proof (its halving and the explicit
/// solver at its stability limit) takes most of the time (a few minutes for the heart).
std::vector<BenchConfig> default_grid();

/// The simulated time compared: `requested_s`, or when 0 the fewest whole beats of the
/// scene's first drive that cover 2 s (a whole number keeps the beat's Fourier component
/// clean). unit: s
double bench_duration_s(const scene::Scene& scene, double requested_s);

/// Every combination of the lists, one config each (explicit and auto steps ignore dt and
/// substeps; only projective uses iterations), duplicates removed.
std::vector<BenchConfig> grid_of(const std::vector<scene::SolverMethod>& methods, const std::vector<double>& dts_s,
                                 const std::vector<int>& substeps, const std::vector<int>& lattices,
                                 const std::vector<int>& iterations = {2});

/// Proves the reference (halving it, refining up to options.max_refinements times, else
/// Error(kDataError) saying what it measured and what to change), asks the second solver,
/// then runs every config; `progress` hears about each run as it starts.
BenchReport run_bench(const scene::Scene& scene, const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress = {});

/// Marks the Pareto front (cost against RMS error) among the finished runs.
void mark_pareto(std::vector<BenchResult>& results);

/// The report for a terminal: the reference and its proof, the table (the frozen baseline
/// first, Pareto runs starred), then every run's beat per driven region.
std::string format_table(const BenchReport& report);

/// One row per run (the baseline, the reference's checks, then the grid) with a header
/// (written atomically); each driven region's amplitude and phase in columns of their own.
void write_csv(const std::filesystem::path& path, const BenchReport& report);

/// Cost (log) against RMS error as a % of the motion (log), one series per solver and model
/// kind, the Pareto front joined.
plot::Figure speed_error_figure(const BenchReport& report);

}  // namespace systole::study
