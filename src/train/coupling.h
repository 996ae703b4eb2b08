#pragma once
// Signals from the coupled body (the paper's training step): the body is tied to the target
// by XPBD attachments (on its render surface, through the surface's embedding when the body
// is a lattice or a myocardium), simulated, and two signals per region are recorded:
// - from forces: at every step, the force the attachments exert (their multipliers / h^2)
//   turned into the change of each region's contraction that would let the springs exert it;
// - from lengths: the contraction whose driven rest lengths best match the lengths the
//   coupled springs actually take (each relative to its rest length).
// The run also gives the floor: how close the body comes to the target while tied to it.

#include <vector>

#include "train/fourier.h"
#include "train/playback.h"

namespace systole::train {

struct RecordedSignals {
  std::vector<double> times_s;                 ///< Recorded step times (measured window). unit: s
  std::vector<std::vector<double>> contraction;  ///< From forces: per region and time, the contraction needed. unit: 1
  std::vector<std::vector<double>> length_contraction;  ///< From lengths: per region and time. unit: 1
  double mean_coupling_force_N = 0;            ///< Mean attachment force per particle: how hard the target pulled. unit: N
  /// The coupled body against the target (drives as written, the scene's coupling): the floor,
  /// what this body reaches held to the target, which a free playback is compared with.
  PlaybackError floor;
};

/// Runs `model` (drives as the scene writes them) coupled to the target with stiffness
/// `coupling_N_per_m` per surface point and axis, over the settling and measured cycles, and
/// records, over the measured ones:
/// - from forces, each region's current contraction plus the least-squares change dc solving
///   J dc = F, F the attachment forces on the particles and J the spring forces' derivative
///   with respect to each region's contraction at the recorded positions (a spring of
///   effective stiffness k - as one XPBD iteration per substep exerts it - and rest L0,
///   shared by regions with weight w, pulls its ends by k L0 w n per unit contraction);
/// - from lengths, the contractions c minimizing sum_s ((L_s(c) - l_s) / L0_s)^2 over the
///   springs of the fitted regions (L_s the driven rest length, sim/forces.h; l_s the
///   spring's length), by Gauss-Newton from the current contractions, lightly regularised
///   towards them so a region no spring sees keeps its drive.
/// Only regions listed in `fitted` get a column; the others keep their drive.
RecordedSignals record_coupled(const Problem& problem, const sim::Model& model, double coupling_N_per_m,
                               const std::vector<int>& fitted);

}  // namespace systole::train
