#include "study/accuracy.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "common/atomic_output.h"
#include "common/error.h"
#include "sim/constraints/volume.h"
#include "sim/model.h"
#include "sim/motion_error.h"
#include "study/driven_regions.h"
#include "world/frame_source.h"
#include "world/world.h"

namespace systole::study {
namespace {

/// "1/240 s" for steps that are a whole fraction of a second, else milliseconds.
std::string step_text(double dt_s) {
  char text[32];
  const double per_s = 1.0 / dt_s;
  if (std::abs(per_s - std::round(per_s)) < 1e-6 * per_s) {
    std::snprintf(text, sizeof text, "1/%.0f s", per_s);
  } else {
    std::snprintf(text, sizeof text, "%.3g ms", dt_s * 1e3);
  }
  return text;
}

/// One run's samples after settling: render-mesh positions of every organ, stacked; each
/// driven region's radial distance; the enclosed volume.
struct Trace {
  sim::Trajectory positions;
  std::vector<std::vector<double>> region_signals;  ///< Per driven region, per sample. unit: m
  std::vector<double> volume;  ///< mesh_volume at each sample. unit: m^3
  std::vector<DrivenRegion> regions;
  double cost_ms_per_s = 0;
  double dt_s = 0;
  int substeps = 0, particles = 0, springs = 0;
  std::string diverged;
};

/// Enclosed volume of the closed render meshes (0 when none is closed). unit: m^3
double mesh_volume(const world::World& world, const std::vector<Eigen::Matrix3Xd>& organ_positions) {
  double volume = 0;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& geometry = world.organs[o].geometry;
    if (geometry.report.encloses_volume()) volume += sim::enclosed_volume(organ_positions[o], geometry.mesh.surface.triangles);
  }
  return volume;
}

/// The scene as `config` runs it, sampled at options.sample_hz from organ time 0.
scene::Scene configured(const scene::Scene& base, const BenchConfig& config, const BenchOptions& options) {
  scene::Scene s = base;
  s.solver.method = config.method;
  s.solver.threads = 1;
  s.solver.auto_dt = config.dt_s == 0;
  if (config.dt_s > 0) s.solver.dt_s = config.dt_s;
  s.solver.substeps = config.substeps;
  s.solver.iterations = config.iterations;
  s.output.fps = options.sample_hz;
  s.output.duration_s = options.settle_s + options.duration_s;
  // The bench samples organ time from 0: a clip's slow motion and loop settling do not apply.
  s.output.slow_motion = 1;
  s.output.loop = false;
  s.output.start_frame = 0;
  for (auto& organ : s.organs) organ.body.lattice = config.lattice;
  return s;
}

/// The configuration's frame source: the scene as configured, built; a refined auto step is
/// rebuilt with the step and substeps auto chose, the substeps multiplied.
std::unique_ptr<world::FrameSource> build(const scene::Scene& base, const BenchConfig& config, const BenchOptions& options) {
  scene::Scene s = configured(base, config, options);
  auto source = std::make_unique<world::FrameSource>(s);
  if (config.dt_s == 0 && config.refine > 1) {
    int substeps = 1;
    for (const auto& body : source->world().organs) substeps = std::max(substeps, body.model.substeps);
    s.solver.auto_dt = false;
    s.solver.dt_s = source->world().dt_s;
    s.solver.substeps = substeps * config.refine;
    source = std::make_unique<world::FrameSource>(s);
  }
  return source;
}

Trace run(const scene::Scene& base, const BenchConfig& config, const BenchOptions& options) {
  const std::unique_ptr<world::FrameSource> source = build(base, config, options);
  const world::World& world = source->world();
  Trace trace;
  trace.regions = driven_regions(base, world);
  trace.region_signals.resize(trace.regions.size());
  trace.dt_s = world.dt_s;
  for (const auto& body : world.organs) {
    trace.substeps = std::max(trace.substeps, body.model.substeps);
    trace.particles += body.model.particle_count();
    trace.springs += body.model.springs.size();
  }
  const int settle = static_cast<int>(std::lround(options.settle_s * options.sample_hz));
  const int samples = static_cast<int>(std::lround(options.duration_s * options.sample_hz));
  std::vector<Eigen::Matrix3Xd> organ_positions(world.organs.size());
  double wall_s = 0;
  // Not a listener: the cost is the advance alone, timed apart from the sampling.
  for (int f = 1; f <= settle + samples; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      source->advance_to(f);
    } catch (const Error& e) {
      if (e.code() != ExitCode::kDiverged) throw;
      trace.diverged = e.what();
      return trace;
    }
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (f <= settle) continue;
    for (std::size_t o = 0; o < world.organs.size(); ++o) source->positions(static_cast<int>(o), organ_positions[o]);
    Eigen::Matrix3Xd all;
    world::stack_positions(organ_positions, all);
    for (std::size_t r = 0; r < trace.regions.size(); ++r) {
      trace.region_signals[r].push_back(radial_excursion_m(trace.regions[r], all));
    }
    trace.positions.push_back(std::move(all));
    trace.volume.push_back(mesh_volume(world, organ_positions));
  }
  trace.cost_ms_per_s = 1e3 * wall_s / (options.settle_s + options.duration_s);
  return trace;
}

/// The rate of the scene's first drive (a region's or a volume drive): the beat. unit: Hz
double beat_rate_hz(const scene::Scene& scene) {
  for (const auto& organ : scene.organs) {
    for (const auto& r : organ.regions) {
      if (r.drive.waveform != scene::Waveform::kNone) return r.drive.rate_hz;
    }
    if (organ.body.volume_drive.waveform != scene::Waveform::kNone) return organ.body.volume_drive.rate_hz;
  }
  return 0;
}

BenchResult compare(const std::string& label, const BenchConfig& config, const Trace& trace, const Trace& reference,
                    double diagonal_m, double sample_hz) {
  BenchResult r;
  r.label = label;
  r.config = config;
  r.diverged = trace.diverged;
  r.dt_s = trace.dt_s;
  r.substeps = trace.substeps;
  r.particles = trace.particles;
  r.springs = trace.springs;
  if (!r.diverged.empty()) return r;
  r.rms_pct_of_motion = sim::error_pct_of_motion(trace.positions, reference.positions);
  r.rms_pct_of_diagonal = 100.0 * sim::rms_distance_m(trace.positions, reference.positions) / diagonal_m;
  double volume_sq = 0;
  for (std::size_t f = 0; f < trace.volume.size(); ++f) {
    const double rel = reference.volume[f] > 0 ? trace.volume[f] / reference.volume[f] - 1.0 : 0.0;
    volume_sq += rel * rel;
  }
  r.volume_error_pct = 100.0 * std::sqrt(volume_sq / double(std::max<std::size_t>(1, trace.volume.size())));
  for (std::size_t k = 0; k < reference.regions.size(); ++k) {
    const sim::SignalAgreement a =
        sim::compare_signals(trace.region_signals[k], reference.region_signals[k], reference.regions[k].rate_hz, sample_hz);
    r.regions.push_back({reference.regions[k].name, a.amplitude_error_pct, a.phase_lag_ms, a.peak_to_peak_error_pct});
  }
  r.cost_ms_per_s = trace.cost_ms_per_s;
  return r;
}

/// The reference's mean shape held still: what a motionless organ scores (100 % of the
/// motion by definition, computed rather than assumed; every beat -100 %).
BenchResult frozen_baseline(const Trace& reference, double diagonal_m) {
  Trace frozen = reference;
  Eigen::Matrix3Xd mean = Eigen::Matrix3Xd::Zero(3, reference.positions.front().cols());
  for (const auto& x : reference.positions) mean += x / double(reference.positions.size());
  for (auto& x : frozen.positions) x = mean;
  for (std::size_t k = 0; k < frozen.regions.size(); ++k) {
    const double m = sim::mean_radial_distance_m(mean, frozen.regions[k].vertices, frozen.regions[k].centre);
    std::fill(frozen.region_signals[k].begin(), frozen.region_signals[k].end(), m);
  }
  frozen.cost_ms_per_s = 0;
  BenchResult r = compare("frozen mean shape", BenchConfig{}, frozen, reference, diagonal_m, 60);
  r.volume_error_pct = std::numeric_limits<double>::quiet_NaN();  // Its volume is not a run's.
  for (auto& b : r.regions) b.phase_lag_ms = std::numeric_limits<double>::quiet_NaN();  // No beat, no phase.
  r.particles = r.springs = r.substeps = 0;
  r.dt_s = 0;
  return r;
}

/// Series of the plot: one per solver and model kind.
std::string series_name(const BenchConfig& c) {
  return std::string(scene::method_name(c.method)) + (c.lattice > 0 ? " lattice" : " full");
}

bool uses_substeps(const BenchConfig& c) { return c.dt_s > 0 && (c.substeps > 1 || c.method == scene::SolverMethod::kXpbd); }

}  // namespace

const RegionBeat* BenchResult::worst_amplitude() const {
  const RegionBeat* worst = nullptr;
  for (const auto& r : regions) {
    if (!worst || std::abs(r.amplitude_error_pct) > std::abs(worst->amplitude_error_pct)) worst = &r;
  }
  return worst;
}

const RegionBeat* BenchResult::worst_phase() const {
  const RegionBeat* worst = nullptr;
  for (const auto& r : regions) {
    if (!std::isnan(r.phase_lag_ms) && (!worst || std::abs(r.phase_lag_ms) > std::abs(worst->phase_lag_ms))) worst = &r;
  }
  return worst;
}

BenchConfig BenchConfig::halved() const {
  BenchConfig c = *this;
  if (dt_s > 0) {
    c.dt_s = dt_s / 2;
  } else {
    c.refine = 2 * refine;
  }
  return c;
}

std::string BenchConfig::label() const {
  std::string text = scene::method_name(method);
  text += " " + (dt_s > 0 ? step_text(dt_s) : std::string("auto"));
  if (uses_substeps(*this)) text += " x" + std::to_string(substeps);
  if (dt_s == 0 && refine > 1) text += " x" + std::to_string(refine);
  if (method == scene::SolverMethod::kProjective) text += " it" + std::to_string(iterations);
  text += lattice > 0 ? " lattice " + std::to_string(lattice) : std::string(" full");
  return text;
}

std::vector<BenchConfig> grid_of(const std::vector<scene::SolverMethod>& methods, const std::vector<double>& dts_s,
                                 const std::vector<int>& substeps, const std::vector<int>& lattices,
                                 const std::vector<int>& iterations) {
  std::vector<BenchConfig> grid;
  for (const auto method : methods) {
    for (const int lattice : lattices) {
      for (const double dt : dts_s) {
        for (const int sub : substeps) {
          for (const int it : iterations) {
            BenchConfig c{method, dt, sub, lattice, it, 1};
            if (method == scene::SolverMethod::kExplicit) c.dt_s = 0;  // Only its stable step makes sense.
            if (c.dt_s == 0) c.substeps = 1;
            if (method != scene::SolverMethod::kProjective) c.iterations = 2;
            const bool seen = std::any_of(grid.begin(), grid.end(), [&](const BenchConfig& g) { return g.label() == c.label(); });
            if (!seen) grid.push_back(c);
          }
        }
      }
    }
  }
  return grid;
}

std::vector<BenchConfig> default_grid() {
  using M = scene::SolverMethod;
  std::vector<BenchConfig> grid = grid_of({M::kProjective}, {1.0 / 60}, {1}, {0}, {1, 2, 3});
  for (const auto& c : grid_of({M::kProjective}, {1.0 / 120, 1.0 / 240}, {1}, {0})) grid.push_back(c);
  for (const auto& c : grid_of({M::kProjective}, {1.0 / 60}, {1}, {12, 20})) grid.push_back(c);
  for (const auto& c : grid_of({M::kImplicit}, {1.0 / 60, 1.0 / 240}, {1}, {0})) grid.push_back(c);
  for (const auto& c : grid_of({M::kXpbd}, {1.0 / 60}, {2}, {0, 12})) grid.push_back(c);
  for (const auto& c : grid_of({M::kXpbd}, {1.0 / 240}, {4, 32}, {0})) grid.push_back(c);
  return grid;
}

double bench_duration_s(const scene::Scene& scene, double requested_s) {
  if (requested_s > 0) return requested_s;
  const double rate = beat_rate_hz(scene);
  return rate > 0 ? std::ceil(2.0 * rate - 1e-9) / rate : 2.0;
}

void mark_pareto(std::vector<BenchResult>& results) {
  for (auto& r : results) {
    r.pareto = r.diverged.empty();
    for (const auto& o : results) {
      if (&o == &r || !o.diverged.empty() || !r.pareto) continue;
      const bool no_worse = o.cost_ms_per_s <= r.cost_ms_per_s && o.rms_pct_of_motion <= r.rms_pct_of_motion;
      const bool better = o.cost_ms_per_s < r.cost_ms_per_s || o.rms_pct_of_motion < r.rms_pct_of_motion;
      if (no_worse && better) r.pareto = false;
    }
  }
}

namespace {

/// The rest shapes' bounding diagonal, from the full models' render meshes. unit: m
double rest_diagonal_m(const scene::Scene& scene) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& organ : scene.organs) {
    for (const auto& p : mesh::build_organ_geometry(organ).mesh.surface.positions) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return (hi - lo).norm();
}

std::string percent(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", v);
  return text;
}

}  // namespace

BenchReport run_bench(const scene::Scene& scene, const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress) {
  if (scene.organs.empty()) throw Error(ExitCode::kDataError, scene.path + ": the scene has no organ to bench");
  BenchReport report;
  report.scene = scene.path;
  report.options = options;
  report.options.duration_s = bench_duration_s(scene, options.duration_s);
  if (report.options.settle_s < 0) {
    const double rate = beat_rate_hz(scene);
    report.options.settle_s = rate > 0 ? 1.0 / rate : 0.0;
  }
  if (report.options.grid.empty()) report.options.grid = default_grid();
  const BenchOptions& o = report.options;
  report.diagonal_m = rest_diagonal_m(scene);
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };

  // The reference, halved until halving no longer moves it.
  report.reference = o.reference;
  report.reference.lattice = 0;
  say("reference: " + report.reference.label());
  Trace reference = run(scene, report.reference, o);
  for (;;) {
    if (!reference.diverged.empty()) throw Error(ExitCode::kDiverged, "the reference run diverged: " + reference.diverged);
    const BenchConfig finer = report.reference.halved();
    say("reference check: " + finer.label());
    const Trace fine = run(scene, finer, o);
    report.self_check = compare("half step: " + finer.label(), finer, fine, reference, report.diagonal_m, o.sample_hz);
    if (report.self_check.diverged.empty() && report.self_check.rms_pct_of_motion <= kReferenceTolerancePct) break;
    if (report.refinements == o.max_refinements) {
      throw Error(ExitCode::kDataError,
                  "the reference is not converged: halving the step of " + report.reference.label() + " moved it by " +
                      (report.self_check.diverged.empty() ? percent(report.self_check.rms_pct_of_motion) : "a divergence") +
                      " of the motion (at most " + percent(kReferenceTolerancePct) + " allowed) after " +
                      std::to_string(report.refinements) +
                      " refinements; lower --reference-dt, raise --reference-substeps, or use --reference-method projective");
    }
    ++report.refinements;
    report.reference = finer;
    reference = fine;
  }
  report.reference_cost_ms_per_s = reference.cost_ms_per_s;
  report.motion_m = sim::rms_motion_m(reference.positions);
  report.frozen = frozen_baseline(reference, report.diagonal_m);
  if (o.check) {
    say("second solver: " + o.check->label());
    report.second_solver = compare("check: " + o.check->label(), *o.check, run(scene, *o.check, o), reference,
                                   report.diagonal_m, o.sample_hz);
  }
  for (std::size_t i = 0; i < o.grid.size(); ++i) {
    const BenchConfig& c = o.grid[i];
    say("[" + std::to_string(i + 1) + "/" + std::to_string(o.grid.size()) + "] " + c.label());
    report.results.push_back(compare(c.label(), c, run(scene, c, o), reference, report.diagonal_m, o.sample_hz));
  }
  mark_pareto(report.results);
  return report;
}

namespace {

void table_row(std::ostream& s, const BenchResult& r, bool starred) {
  char line[512];
  const std::string name = (starred && r.pareto ? "* " : "  ") + r.label;
  if (!r.diverged.empty()) {
    s << name << ": diverged (" << r.diverged << ")\n";
    return;
  }
  const RegionBeat* amp = r.worst_amplitude();
  const RegionBeat* phase = r.worst_phase();
  char beat[64] = "       -        -";
  if (amp) std::snprintf(beat, sizeof beat, "%+8.2f %8s", amp->amplitude_error_pct, phase ? "" : "-");
  if (amp && phase) std::snprintf(beat, sizeof beat, "%+8.2f %+8.1f", amp->amplitude_error_pct, phase->phase_lag_ms);
  char vol[16] = "      -";
  if (!std::isnan(r.volume_error_pct)) std::snprintf(vol, sizeof vol, "%7.3f", r.volume_error_pct);
  char cost[40] = "         -        -";
  if (r.cost_ms_per_s > 0) std::snprintf(cost, sizeof cost, "%10.1f %8.1f", r.cost_ms_per_s, r.realtime_factor());
  std::snprintf(line, sizeof line, "%-40s %9s %4s %6d %7d %9.2f %7.3f %s %s %s\n", name.c_str(),
                r.dt_s > 0 ? step_text(r.dt_s).c_str() : "-", r.substeps > 0 ? std::to_string(r.substeps).c_str() : "-",
                r.particles, r.springs, r.rms_pct_of_motion, r.rms_pct_of_diagonal, vol, beat, cost);
  s << line;
}

}  // namespace

namespace {

/// The reference, its motion and its proof: what every figure of the table rests on.
void reference_lines(std::ostream& s, const BenchReport& report) {
  char line[768];
  const BenchOptions& o = report.options;
  std::snprintf(line, sizeof line,
                "reference: %s, %.2f s compared after %.2f s of settling, sampled at %g Hz; its RMS motion about its mean "
                "shape is %.3f mm (%.2f %% of the %.0f mm bounding diagonal); %.0f ms/sim-s%s\n",
                report.reference.label().c_str(), o.duration_s, o.settle_s, o.sample_hz, 1e3 * report.motion_m,
                100.0 * report.motion_m / report.diagonal_m, 1e3 * report.diagonal_m, report.reference_cost_ms_per_s,
                report.refinements > 0 ? (" (halved " + std::to_string(report.refinements) + " times to converge)").c_str() : "");
  s << line;
  std::snprintf(line, sizeof line, "  self-convergence: at half the step it moves by %.3f %% of the motion (at most %.0f %%)\n",
                report.self_check.rms_pct_of_motion, kReferenceTolerancePct);
  s << line;
  if (!report.second_solver) return;
  const BenchResult& c = *report.second_solver;
  if (!c.diverged.empty()) {
    s << "  second solver: " << c.config.label() << " diverged (" << c.diverged << ")\n";
    return;
  }
  std::snprintf(line, sizeof line, "  second solver: %s (%d substeps) differs by %.3f %% of the motion", c.config.label().c_str(),
                c.substeps, c.rms_pct_of_motion);
  s << line;
  const RegionBeat* amp = c.worst_amplitude();
  const RegionBeat* phase = c.worst_phase();
  if (amp && phase) {
    std::snprintf(line, sizeof line, "; worst beat amplitude %+.2f %% (%s), phase %+.1f ms (%s)", amp->amplitude_error_pct,
                  amp->name.c_str(), phase->phase_lag_ms, phase->name.c_str());
    s << line;
  }
  s << "\n";
}

/// Every run's beat in every periodically driven region.
void beat_block(std::ostream& s, const BenchReport& report) {
  if (report.frozen.regions.empty()) return;
  char line[256];
  s << "\nbeat of each driven region against the reference (amplitude % / phase ms):\n";
  std::snprintf(line, sizeof line, "%-40s", "run");
  s << line;
  for (const auto& region : report.frozen.regions) {
    std::snprintf(line, sizeof line, " %22s", region.name.substr(region.name.find('.') + 1).c_str());
    s << line;
  }
  s << "\n";
  auto beats = [&](const BenchResult& r) {
    if (!r.diverged.empty()) return;
    std::snprintf(line, sizeof line, "%-40s", r.label.c_str());
    s << line;
    for (const auto& b : r.regions) {
      std::snprintf(line, sizeof line, " %+12.2f / %+6.1f", b.amplitude_error_pct, b.phase_lag_ms);
      s << line;
    }
    s << "\n";
  };
  if (report.second_solver) beats(*report.second_solver);
  for (const auto& r : report.results) beats(r);
}

}  // namespace

std::string format_table(const BenchReport& report) {
  std::ostringstream s;
  reference_lines(s, report);
  s << "errors: RMS vertex distance to the reference, % of its motion (a motionless organ: 100) and % of the diagonal; "
       "beat: the worst driven region's amplitude error and phase lag\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-40s %9s %4s %6s %7s %9s %7s %7s %8s %8s %10s %8s\n", "run (* Pareto front)", "step", "sub",
                "parts", "springs", "% motion", "% diag", "vol %", "ampl %", "phase ms", "ms/sim-s", "x real");
  s << line;
  table_row(s, report.frozen, false);
  table_row(s, report.self_check, false);
  if (report.second_solver) table_row(s, *report.second_solver, false);
  for (const auto& r : report.results) table_row(s, r, true);
  beat_block(s, report);
  return s.str();
}

void write_csv(const std::filesystem::path& path, const BenchReport& report) {
  AtomicOutput out(path);
  std::ofstream f(out.temp_path());
  f << "run,method,dt_s,substeps,iterations,lattice,particles,springs,rms_pct_of_motion,rms_pct_of_diagonal,"
       "volume_error_pct,cost_ms_per_sim_s,realtime_factor,pareto,reference_motion_mm";
  for (const auto& region : report.frozen.regions) f << "," << region.name << " amplitude_pct," << region.name << " phase_ms";
  f << ",diverged\n";
  auto row = [&](const BenchResult& r, bool grid) {
    char line[512];
    std::string label = r.label;
    std::replace(label.begin(), label.end(), ',', ';');
    std::snprintf(line, sizeof line, "%s,%s,%.9g,%d,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g", label.c_str(),
                  grid || r.particles > 0 ? scene::method_name(r.config.method) : "", r.dt_s, r.substeps,
                  r.config.iterations, r.config.lattice, r.particles, r.springs, r.rms_pct_of_motion, r.rms_pct_of_diagonal,
                  r.volume_error_pct, r.cost_ms_per_s, r.realtime_factor(), grid && r.pareto ? 1 : 0, 1e3 * report.motion_m);
    f << line;
    for (const auto& b : r.regions) f << "," << b.amplitude_error_pct << "," << b.phase_lag_ms;
    if (r.regions.empty()) {
      for (std::size_t k = 0; k < report.frozen.regions.size(); ++k) f << ",,";
    }
    std::string why = r.diverged;
    std::replace(why.begin(), why.end(), ',', ';');
    std::replace(why.begin(), why.end(), '\n', ' ');
    f << "," << why << "\n";
  };
  row(report.frozen, false);
  row(report.self_check, false);
  if (report.second_solver) row(*report.second_solver, false);
  for (const auto& r : report.results) row(r, true);
  f.close();
  if (!f) throw Error(ExitCode::kIoError, "cannot write " + path.string());
  out.commit();
}

plot::Figure speed_error_figure(const BenchReport& report) {
  plot::Figure fig;
  fig.title = "Speed versus error: " + std::filesystem::path(report.scene).filename().string();
  fig.x = {"RMS vertex error, % of the reference's motion", plot::Scale::kLog};
  fig.y = {"cost, ms of wall time per simulated second (one thread)", plot::Scale::kLog};
  const std::map<scene::SolverMethod, plot::Rgb> colors = {{scene::SolverMethod::kXpbd, {31, 100, 180}},
                                                           {scene::SolverMethod::kImplicit, {40, 150, 70}},
                                                           {scene::SolverMethod::kExplicit, {200, 60, 40}},
                                                           {scene::SolverMethod::kProjective, {140, 60, 170}}};
  std::map<std::string, std::size_t> index;
  std::vector<const BenchResult*> front;
  double lo = 1e300, hi = 0;
  for (const auto& r : report.results) {
    if (!r.diverged.empty() || r.rms_pct_of_motion <= 0 || r.cost_ms_per_s <= 0) continue;
    const std::string name = series_name(r.config);
    if (!index.count(name)) {
      index[name] = fig.series.size();
      plot::Series s;
      s.name = name;
      s.color = colors.at(r.config.method);
      s.marker = r.config.lattice > 0 ? plot::Marker::kDiamond : plot::Marker::kCircle;
      fig.series.push_back(s);
    }
    std::string label = r.config.lattice > 0 ? "L" + std::to_string(r.config.lattice) : std::string();
    if (uses_substeps(r.config)) label += (label.empty() ? "" : " ") + std::string("x") + std::to_string(r.substeps);
    if (r.config.method == scene::SolverMethod::kProjective) {
      label += (label.empty() ? "" : " ") + std::string("it") + std::to_string(r.config.iterations);
    }
    if (r.config.dt_s > 0) label += " " + step_text(r.dt_s);
    fig.series[index[name]].points.push_back({r.rms_pct_of_motion, r.cost_ms_per_s, label});
    if (r.pareto) front.push_back(&r);
    lo = std::min(lo, r.rms_pct_of_motion);
    hi = std::max(hi, r.rms_pct_of_motion);
  }
  if (!front.empty()) {
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->rms_pct_of_motion < b->rms_pct_of_motion; });
    plot::Series s{"Pareto front", {20, 20, 20}, plot::Marker::kRing, true, 16, {}};
    for (const auto* r : front) s.points.push_back({r->rms_pct_of_motion, r->cost_ms_per_s, ""});
    fig.series.push_back(s);
  }
  if (hi > 0) {
    for (const auto& [name, ms, color] : {std::tuple{"real time", 1000.0, plot::Rgb{150, 150, 150}},
                                          std::tuple{"10x real time", 100.0, plot::Rgb{190, 160, 60}}}) {
      plot::Series s{name, color, plot::Marker::kNone, true, 9, {}};
      s.points = {{lo, ms, ""}, {hi, ms, ""}};
      fig.series.push_back(s);
    }
  }
  return fig;
}

}  // namespace systole::study
