#include "train/tune.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <algorithm>
#include <numbers>
#include <sstream>

#include "sim/drive.h"
#include "train/cmaes.h"
#include "train/coupling.h"
#include "train/fourier.h"

namespace systole::train {

namespace {

constexpr double kPi = std::numbers::pi;

/// Maps a search coordinate into [0, 1]: a triangle wave (reflection at the bounds), so
/// every real is a valid point and the map is continuous - bounds without penalties.
double reflect(double y) {
  const double v = y - 2.0 * std::floor(y / 2.0);
  return v <= 1.0 ? v : 2.0 - v;
}

double value_of(const Parameter& p, double y) {
  const double u = y * p.step / (p.hi - p.lo);
  return p.lo + (p.hi - p.lo) * (p.periodic ? u - std::floor(u) : reflect(u));
}

double coordinate_of(const Parameter& p, double value) { return (value - p.lo) / p.step; }

double read(const std::vector<scene::Region>& regions, const Parameter& p) {
  const scene::Drive& d = regions[p.region].drive;
  switch (p.kind) {
    case Parameter::Kind::kAmplitude: return d.amplitude;
    case Parameter::Kind::kHarmonicAmplitude: return d.harmonics[p.harmonic].amplitude;
    case Parameter::Kind::kHarmonicPhase: return std::remainder(d.harmonics[p.harmonic].phase_rad, 2 * kPi);
    case Parameter::Kind::kDelay: return d.delay_s;
    case Parameter::Kind::kLogStiffness: return std::log(regions[p.region].stiffness_scale);
  }
  return 0;
}

void write(std::vector<scene::Region>& regions, const Parameter& p, double v) {
  scene::Drive& d = regions[p.region].drive;
  switch (p.kind) {
    case Parameter::Kind::kAmplitude: d.amplitude = v; break;
    case Parameter::Kind::kHarmonicAmplitude: d.harmonics[p.harmonic].amplitude = v; break;
    case Parameter::Kind::kHarmonicPhase: d.harmonics[p.harmonic].phase_rad = v; break;
    case Parameter::Kind::kDelay: d.delay_s = v; break;
    case Parameter::Kind::kLogStiffness: regions[p.region].stiffness_scale = std::exp(v); break;
  }
}

std::vector<scene::Region> decode(std::vector<scene::Region> regions, const std::vector<Parameter>& params,
                                  const Eigen::VectorXd& y) {
  for (std::size_t i = 0; i < params.size(); ++i) write(regions, params[i], value_of(params[i], y[static_cast<Eigen::Index>(i)]));
  for (auto& r : regions) {
    if (r.drive.waveform == scene::Waveform::kFourier) limit_harmonics(r.drive);
  }
  return regions;
}

/// A region's delay is kept as written when the target locks it, and always with a conduction
/// system: there the excitation times each part's beat, and a region may not write a delay.
bool delay_locked(const scene::Organ& organ, const std::string& region) {
  return organ.electrophysiology.enabled || is_locked(organ.target, region, "delay");
}

/// Each region's mean excitation time over its driven spring ends (sim::Model::excited),
/// from the sinus node's firing; 0 without a conduction system. The fits read a region's
/// recorded signal from it: its springs run its drive from their own excitation. unit: s
std::vector<double> region_activation_s(const sim::Model& model) {
  const int regions = static_cast<int>(model.regions.size());
  std::vector<double> sum(model.regions.size(), 0.0), count(model.regions.size(), 0.0);
  const auto add = [&](int slot) {
    if (slot < regions) return;
    const std::size_t e = static_cast<std::size_t>(slot - regions);
    const std::size_t r = static_cast<std::size_t>(model.excited.region[e]);
    sum[r] += model.excited.delay_s[e];
    count[r] += 1;
  };
  for (std::size_t j = 0; j < model.springs.contraction_a.size(); ++j) {
    add(model.springs.contraction_a[j]);
    add(model.springs.contraction_b[j]);
  }
  for (std::size_t r = 0; r < sum.size(); ++r) sum[r] = count[r] > 0 ? sum[r] / count[r] : 0.0;
  return sum;
}

/// The free parameters of the start regions, with their boxes and first steps.
std::vector<Parameter> free_parameters(const scene::Organ& organ, const std::vector<scene::Region>& start,
                                       const std::vector<bool>& trained) {
  std::vector<Parameter> params;
  const scene::Target& t = organ.target;
  const double period = 1.0 / t.rate_hz;
  for (std::size_t r = 0; r < start.size(); ++r) {
    const scene::Region& region = start[r];
    if (region.pinned) continue;
    auto add = [&](std::string what, Parameter::Kind kind, int harmonic, double lo, double hi, bool periodic, double step) {
      params.push_back({region.name + "." + what, static_cast<int>(r), kind, harmonic, lo, hi, periodic, step});
    };
    if (trained[r] && !is_locked(t, region.name, "amplitude"))
      add("amplitude", Parameter::Kind::kAmplitude, 0, 0.0, 0.95, false, 0.25 * region.drive.amplitude + 0.01);
    if (trained[r] && !is_locked(t, region.name, "shape")) {
      for (std::size_t k = 0; k < region.drive.harmonics.size(); ++k) {
        const std::string h = "harmonic" + std::to_string(k + 1);
        add(h + ".amplitude", Parameter::Kind::kHarmonicAmplitude, static_cast<int>(k), 0.0, 0.5, false, 0.05);
        // Harmonic 1's phase is the delay's job.
        if (k > 0) add(h + ".phase", Parameter::Kind::kHarmonicPhase, static_cast<int>(k), -kPi, kPi, true, 0.3);
      }
    }
    if (trained[r] && !delay_locked(organ, region.name))
      add("delay", Parameter::Kind::kDelay, 0, 0.0, period, true, 0.05 * period);
    if (!is_locked(t, region.name, "stiffness")) {
      const double s0 = region.stiffness_scale;
      add("stiffness", Parameter::Kind::kLogStiffness, 0, std::log(s0 / 10), std::log(std::min(1e6, 10 * s0)), false, 0.3);
    }
  }
  return params;
}

std::string format_error(const PlaybackError& e) {
  std::ostringstream s;
  s.precision(3);
  s << "RMS " << e.rms_pct_of_motion << " % of the target's motion (" << e.rms_pct_of_diagonal << " % of the diagonal), max "
    << e.max_pct_of_diagonal << " % of the diagonal, volume " << e.volume_percent << " %, mean-shape offset "
    << e.mean_offset_pct_of_motion << " % of the motion";
  return s.str();
}

}  // namespace

bool is_locked(const scene::Target& target, const std::string& region, const std::string& param) {
  for (const std::string& entry : target.lock) {
    if (entry == param || entry == region || entry == region + "." + param) return true;
  }
  return false;
}

namespace {

// Which regions' drives are trained: those the scene drives (a region without a drive is
// passive tissue, a lining or a valve the scene only colours, and stays so), not pinned, and
// not every drive parameter locked.
std::vector<int> trained_regions(const scene::Organ& organ, std::vector<bool>& drive_trained) {
  const scene::Target& t = organ.target;
  std::vector<int> fitted_regions;
  drive_trained.assign(organ.regions.size(), false);
  for (std::size_t r = 0; r < organ.regions.size(); ++r) {
    const scene::Region& region = organ.regions[r];
    const bool all_locked = is_locked(t, region.name, "amplitude") && is_locked(t, region.name, "shape") &&
                            delay_locked(organ, region.name);
    if (region.pinned || all_locked || region.drive.waveform == scene::Waveform::kNone) continue;
    drive_trained[r] = true;
    fitted_regions.push_back(static_cast<int>(r));
  }
  return fitted_regions;
}

// A drive whose waveform is kept (`shape` locked) fitted to a contraction signal: the delay
// (on a grid of 360 over the period, then refined by golden section) and the amplitude (least
// squares at that delay) of amplitude x phi(t - delay), each only where not locked too. A
// Fourier fit's amplitude and delay mean something else for a sine or a cardiac waveform
// (its harmonic 1 peaks at phase 0, a sine half a period later).
void fit_kept_waveform(scene::Drive& d, const std::vector<double>& times_s, const std::vector<double>& signal, bool amplitude_free,
                       bool delay_free) {
  auto misfit = [&](double delay, double* best_amplitude) {
    scene::Drive probe = d;
    probe.delay_s = delay;
    double sp = 0, pp = 0;
    std::vector<double> phi(times_s.size());
    for (std::size_t k = 0; k < times_s.size(); ++k) {
      phi[k] = sim::activation(probe, times_s[k], 0.0);
      sp += signal[k] * phi[k], pp += phi[k] * phi[k];
    }
    const double a = amplitude_free ? std::clamp(pp > 0 ? sp / pp : 0.0, 0.0, 0.95) : d.amplitude;
    double sum = 0;
    for (std::size_t k = 0; k < times_s.size(); ++k) sum += std::pow(signal[k] - a * phi[k], 2);
    if (best_amplitude) *best_amplitude = a;
    return sum;
  };
  double delay = d.delay_s;
  if (delay_free) {
    const double period = 1.0 / d.rate_hz;
    const int grid = 360;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < grid; ++i) {
      const double m = misfit(period * i / grid, nullptr);
      if (m < best) best = m, delay = period * i / grid;
    }
    double lo = delay - period / grid, hi = delay + period / grid;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    for (int i = 0; i < 40; ++i) {
      const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
      if (misfit(a, nullptr) < misfit(b, nullptr)) {
        hi = b;
      } else {
        lo = a;
      }
    }
    delay = 0.5 * (lo + hi);
    delay -= period * std::floor(delay / period);
  }
  double amplitude = d.amplitude;
  misfit(delay, &amplitude);
  d.delay_s = delay;
  d.amplitude = amplitude;
}

// The regions with each trained drive fitted as a Fourier series to the recorded signal,
// locked parameters kept as written: CMA-ES's starting point. Each region's signal is read
// from its springs' mean excitation (region_activation_s), as its drive runs from theirs.
std::vector<scene::Region> fitted_regions(const scene::Organ& organ, const sim::Model& model, const std::vector<double>& times_s,
                                          const std::vector<std::vector<double>>& signal,
                                          const std::vector<bool>& drive_trained) {
  const scene::Target& t = organ.target;
  const std::vector<double> activation_s = region_activation_s(model);
  std::vector<scene::Region> start = organ.regions;
  for (std::size_t r = 0; r < start.size(); ++r) {
    scene::Drive& d = start[r].drive;
    if (!drive_trained[r]) {
      if (d.waveform != scene::Waveform::kNone && !start[r].pinned) d.rate_hz = t.rate_hz, d.rate_end_hz = 0;
      continue;
    }
    std::vector<double> times = times_s;
    for (double& time : times) time -= activation_s[r];
    const bool keep_delay = delay_locked(organ, start[r].name);
    if (is_locked(t, start[r].name, "shape")) {
      d.rate_hz = t.rate_hz;
      d.rate_end_hz = 0;
      fit_kept_waveform(d, times, signal[r], !is_locked(t, start[r].name, "amplitude"), !keep_delay);
      continue;
    }
    const scene::Drive fit = drive_from_series(fit_fourier(times, signal[r], t.rate_hz, t.harmonics));
    const scene::Drive written = d;
    d = scene::Drive{};
    d.waveform = scene::Waveform::kFourier;
    d.harmonics = fit.harmonics;
    d.rate_hz = t.rate_hz;
    d.rate_end_hz = 0;
    d.amplitude = is_locked(t, start[r].name, "amplitude") ? written.amplitude : fit.amplitude;
    d.delay_s = keep_delay ? written.delay_s : fit.delay_s;
    // A kept delay: the harmonics' phases carry the fit's timing instead (harmonic k's
    // phase turns by 2 pi k f times the difference), so the series stays where it was fitted.
    for (std::size_t k = 0; keep_delay && k < d.harmonics.size(); ++k)
      d.harmonics[k].phase_rad =
          std::remainder(d.harmonics[k].phase_rad - 2 * kPi * double(k + 1) * t.rate_hz * (fit.delay_s - d.delay_s), 2 * kPi);
  }
  return start;
}

// What the search minimizes: the RMS of the whole surface's error and of each searched
// region's, each as a share of its own motion (% of motion). The whole surface's alone is
// flat in a small region's drive: tuned from drives perturbed by 30 % and 40 ms, the
// anatomical heart's ventricles came back within 5 ms and its atria anywhere (a right atrium
// at 0.009 for 0.10), their motion a small part of the heart's. Where the drives can make
// the target this changes nothing (every share 0); where they cannot, no region is given
// up for the rest. A region the target does not move (NaN) is left out.
double balanced_error(const PlaybackError& e, const std::vector<int>& regions) {
  double sum = e.rms_pct_of_motion * e.rms_pct_of_motion;
  int count = 1;
  for (const int r : regions) {
    const double share = e.regions[static_cast<std::size_t>(r)].rms_pct_of_motion;
    if (std::isnan(share)) continue;
    sum += share * share;
    ++count;
  }
  return std::sqrt(sum / count);
}

// CMA-ES over the free parameters from the fitted start, each playback scored by its
// balanced error, every generation logged.
CmaesResult search(const Problem& problem, const scene::Target& t, const std::vector<scene::Region>& start,
                   const std::vector<Parameter>& parameters, const TuneSettings& settings,
                   const std::function<void(const std::string&)>& log) {
  Eigen::VectorXd y0(static_cast<Eigen::Index>(parameters.size()));
  for (std::size_t i = 0; i < parameters.size(); ++i) y0[static_cast<Eigen::Index>(i)] = coordinate_of(parameters[i], read(start, parameters[i]));

  std::vector<int> searched;  // The regions with a free parameter.
  for (const Parameter& p : parameters) {
    if (std::find(searched.begin(), searched.end(), p.region) == searched.end()) searched.push_back(p.region);
  }
  auto objective = [&](const Eigen::VectorXd& y) {
    const PlaybackError e = play(problem, with_regions(problem.model, decode(start, parameters, y)));
    return e.diverged ? 1e6 : balanced_error(e, searched);
  };
  CmaesSettings cma;
  // Coordinates are in units of each parameter's first step; the fits start within one of
  // the answer (the anatomical heart's round trip: 0.02 to 0.9 steps), so the search starts
  // half a step about it. On that round trip at 500 playbacks, from 1.0: 6.44 % with blood,
  // 5.67 % without and a left atrium 10.5 % off; from 0.5: 7.65 % and 4.80 %, every drive
  // back within 10 % and 10 ms (at generation 10 with blood: 23.1 % balanced, and 20.1 %).
  cma.sigma = 0.5;
  cma.max_evaluations = settings.budget >= 0 ? settings.budget : t.budget;
  cma.seed = settings.seed;
  cma.threads = settings.threads;
  return minimize_cmaes(objective, y0, cma, [&](const CmaesGeneration& g) {
    std::ostringstream s;
    s.precision(4);
    s << "generation " << g.generation << ", " << g.evaluations << " playbacks: best balanced error " << g.best
      << " % of motion";
    log(s.str());
  });
}

// Tuning never hands back drives that play worse than the scene's own: when the search ends
// farther from the target than the drives as written, those are what TUNED.yaml keeps.
void keep_written_if_closer(const scene::Organ& organ, OrganTuning& out, const std::function<void(const std::string&)>& log) {
  if (out.written.diverged || !(out.written.rms_pct_of_motion < out.after.rms_pct_of_motion)) return;
  log("the search ended at " + format_error(out.after) + ", farther than the drives as written; they are kept");
  out.kept_written = true;
  out.regions = organ.regions;
  out.after = out.written;
}

// The tuned drives played at half the scene's step: when this error is the tuned one, the
// error is the drives', not the step's (the accuracy rules: a figure against a converged run).
PlaybackError play_at_half_step(const scene::Scene& scene, std::size_t organ_index, double dt_s,
                                const std::vector<scene::Region>& regions) {
  scene::Scene finer = scene;
  finer.solver.auto_dt = false;
  finer.solver.dt_s = dt_s / 2;
  const Problem fine = make_problem(finer, organ_index);
  return play(fine, with_regions(fine.model, regions));
}

}  // namespace

OrganTuning tune_organ(const scene::Scene& scene, std::size_t organ_index, const TuneSettings& settings) {
  const auto started = std::chrono::steady_clock::now();
  const scene::Organ& organ = scene.organs[organ_index];
  const scene::Target& t = organ.target;
  const std::function<void(const std::string&)> log = [&](const std::string& line) {
    if (settings.log) settings.log(organ.name + ": " + line);
  };
  const Problem problem = make_problem(scene, organ_index);

  OrganTuning out;
  out.organ = organ.name;
  out.target_size = problem.target_size;
  out.measure_start_s = problem.measure_start_s() + problem.dt_s;
  out.target_motion_m = problem.target_motion_m;
  out.target_motion_pct_of_diagonal = 100.0 * problem.target_motion_m / problem.model.rest_extent_m;
  out.dt_s = problem.dt_s;
  out.rate_hz = problem.rate_hz;
  const std::vector<int> fitted = trained_regions(organ, out.drive_trained);

  out.written = play(problem, problem.model);
  log("as written: " + format_error(out.written));

  // Signals from the coupled body, from forces and from lengths, each fitted as Fourier
  // series; the search starts from the one that plays closer to the target.
  const RecordedSignals recorded = record_coupled(problem, problem.model, t.coupling_N_per_m, fitted);
  out.mean_coupling_force_N = recorded.mean_coupling_force_N;
  out.floor = recorded.floor;
  out.coupling_N_per_m = t.coupling_N_per_m;
  out.transfer = problem.target.transfer_note();
  log("floor (the body tied to the target at " + std::to_string(static_cast<int>(t.coupling_N_per_m)) +
      " N/m): " + format_error(out.floor));
  const std::vector<scene::Region> by_forces = fitted_regions(organ, problem.model, recorded.times_s, recorded.contraction, out.drive_trained);
  const std::vector<scene::Region> by_lengths =
      fitted_regions(organ, problem.model, recorded.times_s, recorded.length_contraction, out.drive_trained);
  out.fitted_from_forces = play(problem, with_regions(problem.model, by_forces));
  out.fitted_from_lengths = play(problem, with_regions(problem.model, by_lengths));
  log("fitted from forces: " + format_error(out.fitted_from_forces) + "; mean coupling force " +
      std::to_string(recorded.mean_coupling_force_N) + " N");
  log("fitted from lengths: " + format_error(out.fitted_from_lengths));
  const bool lengths = !(out.fitted_from_forces.rms_pct_of_motion < out.fitted_from_lengths.rms_pct_of_motion);
  const std::vector<scene::Region> start = lengths ? by_lengths : by_forces;
  out.start_from = lengths ? "lengths" : "forces";
  out.fitted = start;
  out.before = lengths ? out.fitted_from_lengths : out.fitted_from_forces;

  out.parameters = free_parameters(organ, start, out.drive_trained);
  const CmaesResult best = search(problem, t, start, out.parameters, settings, log);
  out.regions = decode(start, out.parameters, best.best_x);
  out.after = play(problem, with_regions(problem.model, out.regions));
  keep_written_if_closer(organ, out, log);
  out.generations = best.generations;
  out.evaluations = best.evaluations + 4;  // With the written, two fitted and final playbacks.
  out.stop_reason = best.stop_reason;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  log("tuned: " + format_error(out.after) + " (" + best.stop_reason + ")");
  out.after_half_step = play_at_half_step(scene, organ_index, problem.dt_s, out.regions);
  log("tuned, at half the step: " + format_error(out.after_half_step));
  return out;
}

}  // namespace systole::train
