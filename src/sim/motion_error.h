#pragma once
// How far one run's motion is from another's, measured against the motion itself: an
// error is small only next to what it errs about, so a body frozen in its mean shape
// scores 100 % (docs/accuracy.md). `systole bench` and training's report both speak it.

#include <Eigen/Core>
#include <complex>
#include <vector>

namespace systole::sim {

/// Vertex positions at successive samples, every sample the same vertices. unit: m
using Trajectory = std::vector<Eigen::Matrix3Xd>;

/// The RMS distance of the vertices from their own mean positions over the samples: how
/// much there is to reproduce. unit: m
double rms_motion_m(const Trajectory& frames);

/// The RMS distance between corresponding vertices of two runs over every sample (the
/// shorter run's samples). unit: m
double rms_distance_m(const Trajectory& a, const Trajectory& b);

/// 100 rms_distance(run, reference) / rms_motion(reference): a motionless body in the
/// reference's mean shape scores 100. When the reference does not move at all, 0 if the
/// run matches it and infinity if not. unit: %
double error_pct_of_motion(const Trajectory& run, const Trajectory& reference);

/// The component of a sampled signal at frequency f_hz over the whole run, mean removed:
/// amplitude 2|c|/N and phase arg c, sample i taken at (i + 1) / sample_hz. A periodic
/// signal's fundamental, robust to the drift a cross-correlation trips on.
std::complex<double> fundamental(const std::vector<double>& signal, double f_hz, double sample_hz);

/// The mean distance of `vertices` (indices into x) from `centre`: a region's radial
/// excursion signal, which its contraction lowers and its relaxation raises. unit: m
double mean_radial_distance_m(const Eigen::Matrix3Xd& x, const std::vector<int>& vertices,
                              const Eigen::Vector3d& centre);

/// A run's periodic signal against the reference's at one frequency.
struct SignalAgreement {
  double amplitude_error_pct = 0;  ///< |c| / |c_ref| - 1 of the fundamental. unit: %
  double phase_lag_ms = 0;         ///< How much later the run's fundamental peaks. unit: ms
  double peak_to_peak_error_pct = 0;  ///< (max - min) / (max_ref - min_ref) - 1. unit: %
};

SignalAgreement compare_signals(const std::vector<double>& run, const std::vector<double>& reference, double f_hz,
                                double sample_hz);

}  // namespace systole::sim
