#pragma once
// The twelve-lead ECG of an excitation, in a homogeneous infinite conductor: each node's
// transmembrane potential Vm(t) (electro/action_potential.h) makes a current source density
// where it changes across the muscle, and an electrode at distance R sees
//   phi(e) = -(sigma_i / (4 pi sigma_e)) \int grad Vm . grad(1 / R) dV
// (Plonsey & Barr, "Bioelectricity: A Quantitative Approach", 3rd ed., ch. 8), summed over
// the myocardium's springs as edges of the gradient. The electrodes sit at the standard
// places on a torso laid about the heart's anatomical axes (mesh::Anatomy::body_axes):
// the limb electrodes as Mason & Likar (1966) place them on the torso, the chest ones at
// their intercostal spaces; Wilson's central terminal references V1-V6.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "electro/conduction.h"
#include "electro/ecg.h"
#include "mesh/mesh.h"

namespace systole::electro {

/// Electrode places relative to the heart's centre, in the body's axes (x the patient's
/// left, y the head, z the front). unit: m
struct Electrodes {
  Eigen::Vector3d right_arm, left_arm, left_leg;
  std::array<Eigen::Vector3d, 6> chest;  ///< V1..V6.
};

/// The standard placement (docs/electrophysiology.md gives the places and their sources).
Electrodes standard_electrodes();

/// The ECG of the beats the sinus node starts at `beat_start_s` (ascending; each beat's
/// cycle is the time to the next start, the last one's the one before it), sampled at
/// `rate_hz` over [from_s, to_s). unit: s, Hz
Ecg compute_ecg(const mesh::OrganMesh& mesh, const Excitation& excitation, const std::vector<double>& beat_start_s,
                double from_s, double to_s, double rate_hz, const Electrodes& electrodes = standard_electrodes());

/// A node's transmembrane potential above rest at `since_s` after its activation, for an
/// action potential of `duration_s`: a fast upstroke, a plateau and a slower repolarisation,
/// each a logistic step. The upstroke is widened to the time the front takes to cross a
/// lattice cell (about 5 ms), so the lattice's discrete sources sum to a smooth QRS. unit: mV
double action_potential_mv(double since_s, double duration_s);

}  // namespace systole::electro
