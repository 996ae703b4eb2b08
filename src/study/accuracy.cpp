#include "study/accuracy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "common/atomic_output.h"
#include "common/error.h"
#include "sim/model.h"
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

/// One run's samples: render-mesh positions of every organ, stacked, and the beat signal.
struct Trace {
  std::vector<Eigen::Matrix3Xd> positions;
  std::vector<double> signal;  ///< beat_signal at each sample. unit: m
  std::vector<double> volume;  ///< mesh_volume at each sample. unit: m^3
  double cost_ms_per_s = 0;
  double dt_s = 0;
  int substeps = 0, particles = 0, springs = 0;
  std::string diverged;
};

/// The beat signal: the render meshes' mean distance from rest, which every beat and breath
/// raises and lowers (their volume would not do for a heart: its volume constraint holds it
/// nearly constant while the shape beats). unit: m
double beat_signal(const world::World& world, const std::vector<Eigen::Matrix3Xd>& organ_positions) {
  double displacement = 0;
  Eigen::Index vertices = 0;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& rest = world.organs[o].geometry.mesh.surface.positions;
    for (Eigen::Index v = 0; v < organ_positions[o].cols(); ++v) displacement += (organ_positions[o].col(v) - rest[v]).norm();
    vertices += organ_positions[o].cols();
  }
  return displacement / std::max<Eigen::Index>(1, vertices);
}

/// Enclosed volume of the closed render meshes (0 when none is closed). unit: m^3
double mesh_volume(const world::World& world, const std::vector<Eigen::Matrix3Xd>& organ_positions) {
  double volume = 0;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& geometry = world.organs[o].geometry;
    if (geometry.report.encloses_volume()) volume += sim::enclosed_volume(organ_positions[o], geometry.mesh.surface.triangles);
  }
  return volume;
}

Trace run(const scene::Scene& base, const BenchConfig& config, const BenchOptions& options) {
  scene::Scene s = base;
  s.solver.method = config.method;
  s.solver.threads = 1;
  s.solver.auto_dt = config.dt_s == 0;
  if (config.dt_s > 0) s.solver.dt_s = config.dt_s;
  s.solver.substeps = config.substeps;
  s.output.fps = options.sample_hz;
  s.output.duration_s = options.duration_s;
  // The bench samples organ time from 0: a clip's slow motion and loop settling do not apply.
  s.output.slow_motion = 1;
  s.output.loop = false;
  s.output.start_frame = 0;
  for (auto& organ : s.organs) organ.body.lattice = config.lattice;
  world::World world = world::build_world(s);

  Trace trace;
  trace.dt_s = world.dt_s;
  for (const auto& body : world.organs) {
    trace.substeps = std::max(trace.substeps, body.model.substeps);
    trace.particles += body.model.particle_count();
    trace.springs += body.model.springs.size();
  }
  const int samples = static_cast<int>(std::lround(options.duration_s * options.sample_hz));
  std::vector<Eigen::Matrix3Xd> organ_positions(world.organs.size());
  double wall_s = 0;
  for (int f = 1; f <= samples; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      world::advance_to_frame(world, f);
    } catch (const Error& e) {
      if (e.code() != ExitCode::kDiverged) throw;
      trace.diverged = e.what();
      return trace;
    }
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Eigen::Index total = 0;
    for (std::size_t o = 0; o < world.organs.size(); ++o) {
      world::render_positions(world.organs[o], organ_positions[o]);
      total += organ_positions[o].cols();
    }
    Eigen::Matrix3Xd all(3, total);
    Eigen::Index at = 0;
    for (const auto& p : organ_positions) {
      all.middleCols(at, p.cols()) = p;
      at += p.cols();
    }
    trace.positions.push_back(std::move(all));
    trace.signal.push_back(beat_signal(world, organ_positions));
    trace.volume.push_back(mesh_volume(world, organ_positions));
  }
  trace.cost_ms_per_s = 1e3 * wall_s / options.duration_s;
  return trace;
}

/// The signal's component at frequency f (its Fourier coefficient over the whole run, mean
/// removed): amplitude 2|c|/N and phase arg c. A beat's fundamental, robust to the drift
/// and wrinkles a cross-correlation of raw signals trips on.
std::complex<double> fundamental(const std::vector<double>& signal, double f_hz, double sample_hz) {
  double mean = 0;
  for (double v : signal) mean += v / double(signal.size());
  std::complex<double> c = 0;
  for (std::size_t i = 0; i < signal.size(); ++i) {
    c += (signal[i] - mean) * std::polar(1.0, -2 * M_PI * f_hz * double(i + 1) / sample_hz);
  }
  return 2.0 * c / double(std::max<std::size_t>(1, signal.size()));
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

BenchResult compare(const BenchConfig& config, const Trace& trace, const Trace& reference, double diagonal_m,
                    double sample_hz, double beat_hz) {
  BenchResult r;
  r.config = config;
  r.diverged = trace.diverged;
  r.dt_s = trace.dt_s;
  r.substeps = trace.substeps;
  r.particles = trace.particles;
  r.springs = trace.springs;
  if (!r.diverged.empty()) return r;
  double sum_sq = 0, max_d = 0, volume_sq = 0;
  Eigen::Index count = 0;
  for (std::size_t f = 0; f < trace.positions.size(); ++f) {
    const Eigen::Matrix3Xd d = trace.positions[f] - reference.positions[f];
    const Eigen::VectorXd dist = d.colwise().norm().transpose();
    sum_sq += dist.squaredNorm();
    max_d = std::max(max_d, dist.maxCoeff());
    count += dist.size();
    const double rel = reference.volume[f] > 0 ? trace.volume[f] / reference.volume[f] - 1.0 : 0.0;
    volume_sq += rel * rel;
  }
  r.rms_error_pct = 100.0 * std::sqrt(sum_sq / std::max<Eigen::Index>(1, count)) / diagonal_m;
  r.max_error_pct = 100.0 * max_d / diagonal_m;
  r.volume_error_pct = 100.0 * std::sqrt(volume_sq / std::max<std::size_t>(1, trace.volume.size()));
  if (beat_hz > 0) {
    const std::complex<double> c = fundamental(trace.signal, beat_hz, sample_hz);
    const std::complex<double> c_ref = fundamental(reference.signal, beat_hz, sample_hz);
    if (std::abs(c_ref) > 0) r.amplitude_error_pct = 100.0 * (std::abs(c) / std::abs(c_ref) - 1.0);
    // Lag: a later beat has a more negative phase.
    if (std::abs(c) > 0) r.phase_error_ms = 1e3 * std::arg(c_ref / c) / (2 * M_PI * beat_hz);
  }
  r.cost_ms_per_s = trace.cost_ms_per_s;
  return r;
}

/// Series of the plot: one per solver and model kind.
std::string series_name(const BenchConfig& c) {
  return std::string(scene::method_name(c.method)) + (c.lattice > 0 ? " lattice" : " full");
}

}  // namespace

std::string BenchConfig::label() const {
  std::string text = scene::method_name(method);
  text += " " + (dt_s > 0 ? step_text(dt_s) : std::string("auto"));
  if (method == scene::SolverMethod::kXpbd && dt_s > 0) text += " x" + std::to_string(substeps);
  text += lattice > 0 ? " lattice " + std::to_string(lattice) : std::string(" full");
  return text;
}

std::vector<BenchConfig> grid_of(const std::vector<scene::SolverMethod>& methods, const std::vector<double>& dts_s,
                                 const std::vector<int>& substeps, const std::vector<int>& lattices) {
  std::vector<BenchConfig> grid;
  for (const auto method : methods) {
    for (const int lattice : lattices) {
      for (const double dt : dts_s) {
        for (const int sub : substeps) {
          BenchConfig c{method, dt, sub, lattice};
          if (method == scene::SolverMethod::kExplicit) c.dt_s = 0;  // Only its stable step makes sense.
          if (method != scene::SolverMethod::kXpbd || c.dt_s == 0) c.substeps = 1;
          const bool seen = std::any_of(grid.begin(), grid.end(), [&](const BenchConfig& g) { return g.label() == c.label(); });
          if (!seen) grid.push_back(c);
        }
      }
    }
  }
  return grid;
}

std::vector<BenchConfig> default_grid() {
  using M = scene::SolverMethod;
  std::vector<BenchConfig> grid = grid_of({M::kXpbd}, {1.0 / 240}, {2, 4, 8, 16}, {0});
  for (const auto& c : grid_of({M::kXpbd}, {1.0 / 240, 1.0 / 60}, {1, 2, 4}, {6, 8, 12, 16})) grid.push_back(c);
  for (const auto& c : grid_of({M::kImplicit}, {1.0 / 240, 1.0 / 60}, {1}, {0, 8, 12})) grid.push_back(c);
  for (const auto& c : grid_of({M::kExplicit}, {0}, {1}, {0, 8, 12})) grid.push_back(c);
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
      const bool no_worse = o.cost_ms_per_s <= r.cost_ms_per_s && o.rms_error_pct <= r.rms_error_pct;
      const bool better = o.cost_ms_per_s < r.cost_ms_per_s || o.rms_error_pct < r.rms_error_pct;
      if (no_worse && better) r.pareto = false;
    }
  }
}

BenchReport run_bench(const scene::Scene& scene, const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress) {
  if (scene.organs.empty()) throw Error(ExitCode::kDataError, scene.path + ": the scene has no organ to bench");
  BenchReport report;
  report.scene = scene.path;
  report.options = options;
  report.options.duration_s = bench_duration_s(scene, options.duration_s);
  if (report.options.grid.empty()) report.options.grid = default_grid();

  const BenchConfig reference_config{scene::SolverMethod::kXpbd, options.reference_dt_s, options.reference_substeps, 0};
  if (progress) progress("reference: " + reference_config.label());
  const Trace reference = run(scene, reference_config, report.options);
  if (!reference.diverged.empty()) throw Error(ExitCode::kDiverged, "the reference run diverged: " + reference.diverged);
  report.reference_cost_ms_per_s = reference.cost_ms_per_s;
  {
    // The rest shapes' bounding diagonal, from a world built as the reference was.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    scene::Scene s = scene;
    for (auto& organ : s.organs) organ.body.lattice = 0;
    for (const auto& organ : s.organs) {
      for (const auto& p : mesh::build_organ_geometry(organ).mesh.surface.positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
    report.diagonal_m = (hi - lo).norm();
  }
  for (std::size_t i = 0; i < report.options.grid.size(); ++i) {
    const BenchConfig& c = report.options.grid[i];
    if (progress) progress("[" + std::to_string(i + 1) + "/" + std::to_string(report.options.grid.size()) + "] " + c.label());
    report.results.push_back(
        compare(c, run(scene, c, report.options), reference, report.diagonal_m, options.sample_hz, beat_rate_hz(scene)));
  }
  mark_pareto(report.results);
  return report;
}

std::string format_table(const BenchReport& report) {
  std::ostringstream s;
  char line[512];
  std::snprintf(line, sizeof line, "%-32s %9s %3s %6s %7s %7s %7s %7s %8s %8s %10s %8s\n", "run (* Pareto front)", "step",
                "sub", "parts", "springs", "rms %", "max %", "vol %", "ampl %", "phase ms", "ms/sim-s", "x real");
  s << line;
  for (const auto& r : report.results) {
    const std::string name = (r.pareto ? "* " : "  ") + r.config.label();
    if (!r.diverged.empty()) {
      s << name << ": diverged (" << r.diverged << ")\n";
      continue;
    }
    std::snprintf(line, sizeof line, "%-32s %9s %3d %6d %7d %7.3f %7.3f %7.3f %+8.2f %+8.1f %10.1f %8.1f\n", name.c_str(),
                  step_text(r.dt_s).c_str(), r.substeps, r.particles, r.springs, r.rms_error_pct, r.max_error_pct,
                  r.volume_error_pct, r.amplitude_error_pct, r.phase_error_ms, r.cost_ms_per_s, r.realtime_factor());
    s << line;
  }
  std::snprintf(line, sizeof line,
                "reference: xpbd %s x%d full, %.1f s simulated, sampled at %g Hz; errors in %% of the bounding diagonal "
                "(%.1f mm); reference cost %.0f ms/sim-s\n",
                step_text(report.options.reference_dt_s).c_str(), report.options.reference_substeps,
                report.options.duration_s, report.options.sample_hz, report.diagonal_m * 1e3, report.reference_cost_ms_per_s);
  s << line;
  return s.str();
}

void write_csv(const std::filesystem::path& path, const BenchReport& report) {
  AtomicOutput out(path);
  std::ofstream f(out.temp_path());
  f << "run,method,dt_s,substeps,lattice,particles,springs,rms_error_pct,max_error_pct,volume_error_pct,"
       "amplitude_error_pct,phase_error_ms,cost_ms_per_sim_s,realtime_factor,pareto,diverged\n";
  char line[512];
  for (const auto& r : report.results) {
    std::snprintf(line, sizeof line, "%s,%s,%.9g,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,", r.config.label().c_str(),
                  scene::method_name(r.config.method), r.dt_s, r.substeps, r.config.lattice, r.particles, r.springs,
                  r.rms_error_pct, r.max_error_pct, r.volume_error_pct, r.amplitude_error_pct, r.phase_error_ms,
                  r.cost_ms_per_s, r.realtime_factor(), r.pareto ? 1 : 0);
    std::string why = r.diverged;
    std::replace(why.begin(), why.end(), ',', ';');
    std::replace(why.begin(), why.end(), '\n', ' ');
    f << line << why << "\n";
  }
  f.close();
  if (!f) throw Error(ExitCode::kIoError, "cannot write " + path.string());
  out.commit();
}

plot::Figure speed_error_figure(const BenchReport& report) {
  plot::Figure fig;
  fig.title = "Speed versus error: " + std::filesystem::path(report.scene).filename().string();
  fig.x = {"RMS vertex error, % of the bounding diagonal", plot::Scale::kLog};
  fig.y = {"cost, ms of wall time per simulated second (one thread)", plot::Scale::kLog};
  const std::map<scene::SolverMethod, plot::Rgb> colors = {{scene::SolverMethod::kXpbd, {31, 100, 180}},
                                                           {scene::SolverMethod::kImplicit, {40, 150, 70}},
                                                           {scene::SolverMethod::kExplicit, {200, 60, 40}}};
  std::map<std::string, std::size_t> index;
  std::vector<const BenchResult*> front;
  double lo = 1e300, hi = 0;
  for (const auto& r : report.results) {
    if (!r.diverged.empty() || r.rms_error_pct <= 0 || r.cost_ms_per_s <= 0) continue;
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
    if (r.config.method == scene::SolverMethod::kXpbd && r.config.dt_s > 0) {
      label += (label.empty() ? "" : " ") + std::string("x") + std::to_string(r.substeps);
    }
    if (r.config.dt_s > 0 && r.config.dt_s != 1.0 / 240.0) label += " " + step_text(r.dt_s);
    fig.series[index[name]].points.push_back({r.rms_error_pct, r.cost_ms_per_s, label});
    if (r.pareto) front.push_back(&r);
    lo = std::min(lo, r.rms_error_pct);
    hi = std::max(hi, r.rms_error_pct);
  }
  if (!front.empty()) {
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->rms_error_pct < b->rms_error_pct; });
    plot::Series s{"Pareto front", {20, 20, 20}, plot::Marker::kRing, true, 16, {}};
    for (const auto* r : front) s.points.push_back({r->rms_error_pct, r->cost_ms_per_s, ""});
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
