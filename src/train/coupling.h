#pragma once
// Signals from forces (the paper's training step): the body is tied to the target by
// XPBD attachments, simulated, and at every step the force the attachments exert (their
// multipliers / h^2) is turned into the change of each region's contraction that would let
// the springs exert it instead. The per-region contraction signals that result are fitted as
// Fourier series.

#include <vector>

#include "train/fourier.h"
#include "train/playback.h"

namespace systole::train {

struct RecordedSignals {
  std::vector<double> times_s;                 ///< Recorded step times (measured window). unit: s
  std::vector<std::vector<double>> contraction;  ///< Per region and time: the contraction needed. unit: 1
  double mean_coupling_force_N = 0;            ///< Mean attachment force per particle: how hard the target pulled. unit: N
};

/// Runs `model` (drives as the scene writes them) coupled to the target with stiffness
/// `coupling_N_per_m` per particle and axis, over the settling and measured cycles, and
/// records, over the measured ones, each region's needed contraction: its current
/// contraction plus the least-squares change dc solving J dc = F, where F holds the
/// attachment forces and J the spring forces' derivative with respect to each region's
/// contraction at the recorded positions (a spring of effective stiffness k - as one XPBD
/// iteration per substep exerts it - and rest L0, shared by regions with weight w, pulls its
/// ends by k L0 w n per unit contraction). Only regions
/// listed in `fitted` get a column; the others keep their drive.
RecordedSignals record_coupled(const Problem& problem, const sim::Model& model, double coupling_N_per_m,
                               const std::vector<int>& fitted);

}  // namespace systole::train
