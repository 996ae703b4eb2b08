#include "sim/drive.h"

#include "common/spline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace systole::sim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Raised-cosine pulse over [0, width): 0 at the ends, 1 in the middle.
double raised_cosine(double u, double width) {
  if (u >= width) return 0.0;
  return 0.5 * (1.0 - std::cos(kTwoPi * u / width));
}

/// The same pulse with its peak at `peak` x width: a rising half-cosine, then a falling one.
double skewed_raised_cosine(double u, double width, double peak) {
  if (u >= width) return 0.0;
  const double rise = peak * width;
  if (u < rise) return 0.5 * (1.0 - std::cos(std::numbers::pi * u / rise));
  return 0.5 * (1.0 + std::cos(std::numbers::pi * (u - rise) / (width - rise)));
}

}  // namespace

double drive_cycles(const Drive& drive, double t_s, double ramp_s) {
  if (drive.rate_end_hz <= 0 || ramp_s <= 0) return drive.rate_hz * t_s;
  const double f0 = drive.rate_hz, f1 = drive.rate_end_hz;
  const double t = std::min(t_s, ramp_s);
  double cycles = f0 * t + 0.5 * (f1 - f0) * t * t / ramp_s;
  if (t_s > ramp_s) cycles += f1 * (t_s - ramp_s);
  return cycles;
}

double waveform_value(const Drive& drive, double u) {
  switch (drive.waveform) {
    case Waveform::kNone:
      return 0.0;
    case Waveform::kSine:
      return 0.5 * (1.0 - std::cos(kTwoPi * u + drive.phase_rad));
    case Waveform::kFourier: {
      double phi = 0.5;
      for (std::size_t k = 0; k < drive.harmonics.size(); ++k) {
        const auto& h = drive.harmonics[k];
        phi += h.amplitude * std::cos(kTwoPi * double(k + 1) * u + h.phase_rad + drive.phase_rad);
      }
      return std::clamp(phi, 0.0, 1.0);
    }
    case Waveform::kCardiac:
      // Contraction occupies the systolic fraction of the beat; diastole is at rest. (The
      // symmetric pulse keeps its own formula: the same bits as before peak_fraction came.)
      if (drive.peak_fraction == 0.5) return raised_cosine(u, drive.systolic_fraction);
      return skewed_raised_cosine(u, drive.systolic_fraction, drive.peak_fraction);
    case Waveform::kBreathing: {
      // Active inhale (rising half-cosine), then a slower passive exhale.
      const double in = drive.inhale_fraction;
      if (u < in) return 0.5 * (1.0 - std::cos(std::numbers::pi * u / in));
      return 0.5 * (1.0 + std::cos(std::numbers::pi * (u - in) / (1.0 - in)));
    }
    case Waveform::kSamples: {
      const auto& s = drive.samples;
      if (s.empty()) return 0.0;
      const double x = u * double(s.size());
      const std::size_t i = std::min(static_cast<std::size_t>(x), s.size() - 1);
      const double f = x - double(i);
      // Periodic Catmull-Rom: smooth, passes through every sample.
      return std::clamp(periodic_catmull_rom(s, i, f), 0.0, 1.0);
    }
  }
  return 0.0;
}

double activation(const Drive& drive, double t_s, double ramp_s, const std::vector<double>& beats) {
  if (drive.waveform == Waveform::kNone || drive.rate_hz <= 0) return 0.0;
  const double local_t = t_s - drive.delay_s;
  if (local_t < 0 && drive.waveform != Waveform::kSine && drive.waveform != Waveform::kFourier) {
    return 0.0;  // Templates start at rest; the delay only postpones the first beat.
  }
  const double cycles = drive_cycles(drive, local_t, ramp_s);
  if (beats.size() >= 2 && cycles >= 0 && cycles < beats.back()) {
    const auto next = std::upper_bound(beats.begin(), beats.end(), cycles);
    const double start = *(next - 1), end = *next;
    return waveform_value(drive, (cycles - start) / (end - start));
  }
  const double u = cycles - std::floor(cycles);
  return waveform_value(drive, u);
}

void region_contractions(const std::vector<RegionParams>& regions, const std::vector<std::vector<double>>& beats,
                         double t_s, double ramp_s, Eigen::VectorXd& out) {
  static const std::vector<double> regular;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& d = regions[r].drive;
    out[static_cast<Eigen::Index>(r)] = d.amplitude * activation(d, t_s, ramp_s, r < beats.size() ? beats[r] : regular);
  }
}

namespace {

/// SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators",
/// OOPSLA 2014): a counter-based hash, so draw k needs no earlier draws.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

std::vector<double> irregular_beats(double irregularity, std::uint64_t seed, std::uint64_t stream, double cycles) {
  std::vector<double> b = {0.0};
  for (std::uint64_t k = 0; b.back() <= cycles + 1.0; ++k) {
    const std::uint64_t h = splitmix64(splitmix64(seed ^ (stream * 0x632be59bd9b4e019ull)) + k);
    const double u = double(h >> 11) * 0x1.0p-53 * 2.0 - 1.0;  // Uniform in [-1, 1).
    b.push_back(b.back() + 1.0 + irregularity * u);
  }
  return b;
}

std::vector<double> beat_start_times(const Drive& d, const std::vector<double>& beats, double ramp_s,
                                     double until_s) {
  std::vector<double> out;
  const double total = drive_cycles(d, until_s, ramp_s);
  for (std::size_t k = 0;; ++k) {
    const double c = beats.size() >= 2 ? (k < beats.size() ? beats[k] : beats.back() + double(k + 1 - beats.size()))
                                       : double(k);
    if (c > total) break;
    double lo = 0, hi = until_s;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (drive_cycles(d, mid, ramp_s) < c ? lo : hi) = mid;
    }
    out.push_back(d.delay_s + hi);
  }
  return out;
}

double highest_frequency_hz(const Drive& drive) {
  const double rate = std::max(drive.rate_hz, drive.rate_end_hz);
  switch (drive.waveform) {
    case Waveform::kNone:
      return 0.0;
    case Waveform::kSine:
      return rate;
    case Waveform::kFourier:
      return rate * double(std::max<std::size_t>(1, drive.harmonics.size()));
    case Waveform::kCardiac:
      // The shorter half of the pulse, as a half-period of a cosine.
      return rate / (2.0 * std::min(drive.peak_fraction, 1.0 - drive.peak_fraction) * drive.systolic_fraction);
    case Waveform::kBreathing:
      return rate / (2.0 * std::min(drive.inhale_fraction, 1.0 - drive.inhale_fraction));
    case Waveform::kSamples:
      return rate * double(std::max<std::size_t>(1, drive.samples.size())) / 2.0;
  }
  return rate;
}

}  // namespace systole::sim
