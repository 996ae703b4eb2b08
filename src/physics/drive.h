#pragma once
// A region's rhythm and a point's path in time: the values a scene gives and the simulator
// runs on, declared once (scene/drive.h and sim/params.h both use these). Every quantity in
// SI units, whatever unit the YAML used.

#include <Eigen/Core>
#include <vector>

namespace systole::physics {

// ---------------------------------------------------------------------------------------
// Drive: the periodic activation phi(t) that shortens a region's springs,
// L(t) = L0 * (1 - amplitude * phi(t - delay)), phi in [0, 1] for the templates;
// sim/drive.h evaluates it.

enum class Waveform {
  kNone,       ///< No drive: the region is passive.
  kSine,       ///< phi = (1 - cos(2 pi f t + phase)) / 2.
  kFourier,    ///< phi = 1/2 + sum_k a_k cos(2 pi k f t + phase_k), harmonics from k = 1.
  kCardiac,    ///< Raised-cosine contraction over the systolic fraction of each beat, peaking at peak_fraction of it.
  kBreathing,  ///< Asymmetric: raised-cosine inhale over inhale_fraction, slower exhale.
  kSamples,    ///< A table of phi over one period, interpolated periodically.
};

struct Harmonic {
  double amplitude = 0;  ///< Relative to the drive amplitude. unit: 1
  double phase_rad = 0;  ///< unit: rad
};

struct Drive {
  Waveform waveform = Waveform::kNone;
  double rate_hz = 0;               ///< Cycles per second at the start of the clip. unit: Hz
  double rate_end_hz = 0;           ///< When > 0, the rate ramps linearly to this by the clip's end. unit: Hz
  double amplitude = 0;             ///< Fraction of rest length removed at phi = 1. unit: 1, in [0, 1)
  double phase_rad = 0;             ///< unit: rad
  double delay_s = 0;               ///< Activation delay (atria before ventricles). unit: s
  std::vector<Harmonic> harmonics;  ///< kFourier: harmonic k = index + 1.
  double systolic_fraction = 0.35;  ///< kCardiac: part of the period spent contracting. unit: 1
  double peak_fraction = 0.5;       ///< kCardiac: where in that part the contraction peaks. unit: 1
  double inhale_fraction = 0.4;     ///< kBreathing: part of the period spent inhaling. unit: 1
  std::vector<double> samples;      ///< kSamples: phi over one period, evenly spaced.
  double irregularity = 0;          ///< Seeded beat-to-beat jitter of the period (0 = regular). unit: 1
};

/// A position at a time: a key of a grab's handle path or of a kinematic region's motion,
/// interpolated smoothly (Catmull-Rom, common/spline.h) between keys and held outside them.
struct PathKey {
  double time_s = 0;                                     ///< unit: s
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< unit: m
};

}  // namespace systole::physics
