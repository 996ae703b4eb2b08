#pragma once
// Speed versus error (`systole bench`): the scene's organs run over a grid of solver x
// step x model configurations and are compared with a reference run (tiny step, full
// model, many substeps). Error is measured on the render mesh, so full and reduced models
// are judged by what the viewer sees.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "plot/plot.h"
#include "scene/scene.h"

namespace systole::study {

struct BenchConfig {
  scene::SolverMethod method = scene::SolverMethod::kXpbd;
  double dt_s = 1.0 / 240.0;  ///< 0: the longest stable step (solver.dt: auto). unit: s
  int substeps = 4;           ///< XPBD only; auto steps choose their own.
  int lattice = 0;            ///< body.lattice: 0 full model, else voxels along the longest side.

  std::string label() const;  ///< "xpbd 1/240 s x4 full", "explicit auto lattice 8".
};

struct BenchResult {
  BenchConfig config;
  std::string diverged;           ///< Why the run blew up; empty: it finished.
  double dt_s = 0;                ///< The step used (after rounding to the sample period). unit: s
  int substeps = 0;               ///< Substeps used.
  int particles = 0, springs = 0;
  double rms_error_pct = 0;       ///< RMS vertex distance to the reference over the run, % of the bounding diagonal.
  double max_error_pct = 0;       ///< Largest vertex distance at any sample, % of the diagonal.
  double volume_error_pct = 0;    ///< RMS of (V - V_ref) / V_ref over the run. unit: %
  double amplitude_error_pct = 0; ///< Beat amplitude against the reference's: the drive-rate component of the mean distance from rest. unit: %
  double phase_error_ms = 0;      ///< Lag of that component behind the reference's. unit: ms
  double cost_ms_per_s = 0;       ///< Wall time per simulated second on one thread. unit: ms/s
  bool pareto = false;            ///< No other run is both cheaper and more accurate.

  double realtime_factor() const { return cost_ms_per_s > 0 ? 1000.0 / cost_ms_per_s : 0; }
};

struct BenchOptions {
  double duration_s = 0;               ///< Simulated time per run; 0: whole beats covering 2 s (bench_duration_s). unit: s
  double sample_hz = 60;               ///< How often positions are compared; steps are at most this long. unit: Hz
  double reference_dt_s = 1.0 / 960.0; ///< unit: s
  int reference_substeps = 32;
  std::vector<BenchConfig> grid;       ///< Empty: default_grid().
};

struct BenchReport {
  std::string scene;
  double diagonal_m = 0;             ///< Bounding diagonal of the render meshes at rest. unit: m
  double reference_cost_ms_per_s = 0;  ///< unit: ms/s
  BenchOptions options;
  std::vector<BenchResult> results;
};

/// The grid `systole bench` runs when not narrowed: XPBD at several substep counts on the
/// full model and on lattices, the implicit solver, and the paper's explicit method at its
/// stable step (full and reduced). The reference and the full explicit run take most of
/// the time (a few minutes for the shipped heart).
std::vector<BenchConfig> default_grid();

/// The simulated time of each run: `requested_s`, or when 0 the fewest whole beats of the
/// scene's first drive that cover 2 s (a whole number keeps the beat's Fourier component
/// clean). unit: s
double bench_duration_s(const scene::Scene& scene, double requested_s);

/// Every combination of the lists, one config each (explicit and auto steps ignore dt and
/// substeps; implicit ignores substeps), duplicates removed.
std::vector<BenchConfig> grid_of(const std::vector<scene::SolverMethod>& methods, const std::vector<double>& dts_s,
                                 const std::vector<int>& substeps, const std::vector<int>& lattices);

/// Runs the reference, then every config; `progress` hears about each run as it starts.
BenchReport run_bench(const scene::Scene& scene, const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress = {});

/// Marks the Pareto front (cost against RMS error) among the finished runs.
void mark_pareto(std::vector<BenchResult>& results);

/// The table for a terminal, one row per run, Pareto runs starred.
std::string format_table(const BenchReport& report);

/// One row per run, with a header (written atomically).
void write_csv(const std::filesystem::path& path, const BenchReport& report);

/// Cost (log) against RMS error (log), one series per solver and model kind, the Pareto
/// front joined.
plot::Figure speed_error_figure(const BenchReport& report);

}  // namespace systole::study
