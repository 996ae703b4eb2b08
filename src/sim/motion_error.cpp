#include "sim/motion_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace systole::sim {

double rms_motion_m(const Trajectory& frames) {
  if (frames.empty()) return 0;
  Eigen::Matrix3Xd mean = Eigen::Matrix3Xd::Zero(3, frames.front().cols());
  for (const auto& x : frames) mean += x;
  mean /= double(frames.size());
  double sum_sq = 0;
  for (const auto& x : frames) sum_sq += (x - mean).colwise().squaredNorm().sum();
  const double count = double(frames.size()) * double(std::max<Eigen::Index>(1, mean.cols()));
  return std::sqrt(sum_sq / count);
}

double rms_distance_m(const Trajectory& a, const Trajectory& b) {
  const std::size_t samples = std::min(a.size(), b.size());
  if (samples == 0) return 0;
  double sum_sq = 0;
  for (std::size_t f = 0; f < samples; ++f) sum_sq += (a[f] - b[f]).colwise().squaredNorm().sum();
  const double count = double(samples) * double(std::max<Eigen::Index>(1, a.front().cols()));
  return std::sqrt(sum_sq / count);
}

double error_pct_of_motion(const Trajectory& run, const Trajectory& reference) {
  const double error = rms_distance_m(run, reference);
  const double motion = rms_motion_m(reference);
  if (motion > 0) return 100.0 * error / motion;
  return error > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

std::complex<double> fundamental(const std::vector<double>& signal, double f_hz, double sample_hz) {
  if (signal.empty()) return 0;
  double mean = 0;
  for (double v : signal) mean += v / double(signal.size());
  std::complex<double> c = 0;
  for (std::size_t i = 0; i < signal.size(); ++i) {
    c += (signal[i] - mean) * std::polar(1.0, -2 * M_PI * f_hz * double(i + 1) / sample_hz);
  }
  return 2.0 * c / double(signal.size());
}

double mean_radial_distance_m(const Eigen::Matrix3Xd& x, const std::vector<int>& vertices,
                              const Eigen::Vector3d& centre) {
  if (vertices.empty()) return 0;
  double sum = 0;
  for (int v : vertices) sum += (x.col(v) - centre).norm();
  return sum / double(vertices.size());
}

SignalAgreement compare_signals(const std::vector<double>& run, const std::vector<double>& reference, double f_hz,
                                double sample_hz) {
  SignalAgreement out;
  const std::complex<double> c = fundamental(run, f_hz, sample_hz);
  const std::complex<double> c_ref = fundamental(reference, f_hz, sample_hz);
  if (std::abs(c_ref) > 0) out.amplitude_error_pct = 100.0 * (std::abs(c) / std::abs(c_ref) - 1.0);
  // A later peak has a more negative phase.
  if (std::abs(c) > 0 && std::abs(c_ref) > 0) out.phase_lag_ms = 1e3 * std::arg(c_ref / c) / (2 * M_PI * f_hz);
  auto span = [](const std::vector<double>& s) {
    if (s.empty()) return 0.0;
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    return *hi - *lo;
  };
  const double ref_span = span(reference);
  if (ref_span > 0) out.peak_to_peak_error_pct = 100.0 * (span(run) / ref_span - 1.0);
  return out;
}

}  // namespace systole::sim
