#pragma once
// Region activation signals: phi(t) in [0, 1] (0 relaxed, 1 fully contracted) that set
// the rest lengths L(t) = L0 * (1 - amplitude * phi(t - delay)) of a region's springs
// (Kenwright & Sinmai, "Lightweight Self-Driven Deformable Organ Animations", §3).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "sim/params.h"

namespace systole::sim {

/// Number of cycles completed by time t_s: the integral of the rate, which may ramp
/// linearly from rate_hz to rate_end_hz over [0, ramp_s] and stay there. unit: cycles
double drive_cycles(const Drive& drive, double t_s, double ramp_s);

/// phi of one period's waveform at fraction u of the period, u in [0, 1). unit: 1
double waveform_value(const Drive& drive, double u);

/// The activation phi at time t_s (delay applied; before the delay the region is at rest
/// phase 0). `ramp_s` is the clip length over which a rate ramp runs. `beats`, when not
/// empty, are irregular beat boundaries in cycles (see irregular_beats): beat k spans
/// cycles [beats[k], beats[k+1]) and the waveform is stretched over it.
double activation(const Drive& drive, double t_s, double ramp_s, const std::vector<double>& beats = {});

/// Seeded irregular beat boundaries for a drive with irregularity r > 0: b0 = 0 and
/// b(k+1) = b(k) + 1 + r u(k), u(k) uniform in [-1, 1] from a hash of (seed, stream, k), so
/// a beat's length does not depend on what else was drawn. Covers `cycles` cycles.
std::vector<double> irregular_beats(double irregularity, std::uint64_t seed, std::uint64_t stream, double cycles);

/// Rest-length contraction of every region at time t: amplitude * phi(t), into `out`
/// (sized to the region count).
void region_contractions(const std::vector<RegionParams>& regions, const std::vector<std::vector<double>>& beats,
                         double t_s, double ramp_s, Eigen::VectorXd& out);

/// The times a drive's beats start (its cycle boundaries, or the seeded irregular ones in
/// `beats`, delay applied) up to `until_s`, found by bisection on the (monotonic) cycle
/// count. unit: s
std::vector<double> beat_start_times(const Drive& drive, const std::vector<double>& beats, double ramp_s,
                                     double until_s);

/// Highest frequency present in the drive at any time: rate x highest harmonic, or the
/// sharpest template's equivalent. unit: Hz
double highest_frequency_hz(const Drive& drive);

}  // namespace systole::sim
