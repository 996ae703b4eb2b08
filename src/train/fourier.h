#pragma once
// Periodic signals as Fourier series, fitted by least squares, and their form as a
// region drive: c(t) = A (1/2 + sum_k a_k cos(2 pi k f (t - delay) + p_k)), the `fourier`
// waveform of sim/drive.h.

#include <vector>

#include "scene/scene.h"

namespace systole::train {

/// c(t) = mean + sum_k (cos_k cos(2 pi k f t) + sin_k sin(2 pi k f t)), k = 1..harmonics.
struct FourierSeries {
  double rate_hz = 0;  ///< f. unit: Hz
  double mean = 0;
  std::vector<double> cos_terms, sin_terms;

  double operator()(double t_s) const;
};

/// Least-squares fit of samples (t_i, c_i) with `harmonics` harmonics at rate f (Eigen's
/// column-pivoting QR on the design matrix).
FourierSeries fit_fourier(const std::vector<double>& times_s, const std::vector<double>& values, double rate_hz,
                          int harmonics);

/// The drive whose contraction A phi(t - delay) is the series: A = 2 mean, a_k = |c_k| / A,
/// the first harmonic's phase moved into the delay (so p_1 = 0; delay in [0, 1/f)). A drive
/// can only shorten springs, so when the harmonics outweigh the mean (the series would dip
/// below 0) the mean is raised to their sum; A is capped at 0.95.
scene::Drive drive_from_series(const FourierSeries& series);

/// Scales a fourier drive's harmonic amplitudes down so they sum to at most 1/2 (phi then
/// stays within [0, 1], as the scene schema requires).
void limit_harmonics(scene::Drive& drive);

/// The contraction A phi(t) of a drive: the series a fourier drive stands for.
FourierSeries series_from_drive(const scene::Drive& drive);

}  // namespace systole::train
