#include "train/fourier.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace systole::train {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

double FourierSeries::operator()(double t_s) const {
  double c = mean;
  for (std::size_t k = 0; k < cos_terms.size(); ++k) {
    const double w = kTwoPi * double(k + 1) * rate_hz * t_s;
    c += cos_terms[k] * std::cos(w) + sin_terms[k] * std::sin(w);
  }
  return c;
}

FourierSeries fit_fourier(const std::vector<double>& times_s, const std::vector<double>& values, double rate_hz,
                          int harmonics) {
  const Eigen::Index rows = static_cast<Eigen::Index>(times_s.size());
  Eigen::MatrixXd design(rows, 1 + 2 * harmonics);
  Eigen::VectorXd rhs(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    design(i, 0) = 1.0;
    for (int k = 1; k <= harmonics; ++k) {
      const double w = kTwoPi * k * rate_hz * times_s[i];
      design(i, 2 * k - 1) = std::cos(w);
      design(i, 2 * k) = std::sin(w);
    }
    rhs[i] = values[i];
  }
  const Eigen::VectorXd x = design.colPivHouseholderQr().solve(rhs);
  FourierSeries s;
  s.rate_hz = rate_hz;
  s.mean = x[0];
  for (int k = 1; k <= harmonics; ++k) {
    s.cos_terms.push_back(x[2 * k - 1]);
    s.sin_terms.push_back(x[2 * k]);
  }
  return s;
}

scene::Drive drive_from_series(const FourierSeries& series) {
  scene::Drive d;
  d.waveform = scene::Waveform::kFourier;
  d.rate_hz = series.rate_hz;
  const std::size_t n = series.cos_terms.size();
  std::vector<double> magnitude(n), phase(n);
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    // cos_k cos(w) + sin_k sin(w) = m cos(w + p) with m = |(cos_k, sin_k)|, p = -atan2(sin_k, cos_k).
    magnitude[k] = std::hypot(series.cos_terms[k], series.sin_terms[k]);
    phase[k] = -std::atan2(series.sin_terms[k], series.cos_terms[k]);
    sum += magnitude[k];
  }
  const double mean = std::max(series.mean, sum);
  d.amplitude = std::min(0.95, 2.0 * mean);
  if (d.amplitude <= 0) return d;
  // phi(t - delay) puts -2 pi k f delay on harmonic k: choose delay so harmonic 1 has phase 0.
  const double period = 1.0 / series.rate_hz;
  const double shift_cycles = n > 0 ? -phase[0] / kTwoPi : 0.0;
  d.delay_s = period * (shift_cycles - std::floor(shift_cycles));
  const double scale = 2.0 * mean / d.amplitude;  // > 1 only where A was capped.
  for (std::size_t k = 0; k < n; ++k) {
    double p = phase[k] + kTwoPi * double(k + 1) * series.rate_hz * d.delay_s;
    p = std::remainder(p, kTwoPi);
    d.harmonics.push_back({scale * magnitude[k] / (2.0 * mean), k == 0 ? 0.0 : p});
  }
  limit_harmonics(d);
  return d;
}

void limit_harmonics(scene::Drive& drive) {
  double sum = 0;
  for (const auto& h : drive.harmonics) sum += h.amplitude;
  // A hair below 1/2, so the sum still passes the schema's check after the scene writer
  // rounds each amplitude to 10 digits.
  const double limit = 0.5 - 1e-8;
  if (sum <= limit) return;
  for (auto& h : drive.harmonics) h.amplitude *= limit / sum;
}

FourierSeries series_from_drive(const scene::Drive& drive) {
  FourierSeries s;
  s.rate_hz = drive.rate_hz;
  s.mean = 0.5 * drive.amplitude;
  for (std::size_t k = 0; k < drive.harmonics.size(); ++k) {
    const double w0 = -kTwoPi * double(k + 1) * drive.rate_hz * drive.delay_s + drive.harmonics[k].phase_rad + drive.phase_rad;
    const double m = drive.amplitude * drive.harmonics[k].amplitude;
    s.cos_terms.push_back(m * std::cos(w0));
    s.sin_terms.push_back(-m * std::sin(w0));
  }
  return s;
}

}  // namespace systole::train
