#pragma once
// The forces of the mass-spring-damper body (Kenwright & Sinmai §3): what the explicit
// and implicit solvers integrate. XPBD works on the same springs as constraints instead.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "sim/drive.h"
#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Rest length of spring j given the regions' current contraction c (the mean of its two
/// ends'). A spring without fibres shortens by c. In muscle with fibres the contraction is an
/// orthotropic active strain (Rossi et al. 2012, "Orthotropic active strain models for the
/// numerical simulation of cardiac biomechanics", Int J Numer Meth Biomed Eng 28:761): the
/// fibre shortens to 1 - c, the cross-fibre direction in the wall to 1 - k c (k the spring's
/// cross-fibre ratio: cross-fibre shortening is measured in vivo, Costa et al. 1999), and the
/// direction across the wall lengthens to 1 / ((1 - c)(1 - k c)) so the muscle keeps its
/// volume; a spring takes the length that stretch gives its direction.
/// Beside this strain the fibre pulls with a tension of its own (an active stress, as in
/// Nash & Panfilov 2004, "Electromechanical model of excitable tissue to study reentrant
/// cardiac arrhythmias", Prog Biophys Mol Biol 85:501): its rest length shortens by a further
/// 1 - t c (t = fibre_tension) that the other directions do not take up. A strain alone
/// prescribes each layer's shape, so the lining's and the outside's opposite helices cancel
/// each other's shear; a tension lets the layer that pulls harder win, which is what twists a
/// ventricle (docs/anatomy.md). unit: m
inline double driven_rest_length(const Springs& sp, int j, const Eigen::VectorXd& contraction) {
  const int ia = sp.contraction_a.empty() ? sp.region_a[j] : sp.contraction_a[j];
  const int ib = sp.contraction_b.empty() ? sp.region_b[j] : sp.contraction_b[j];
  const double ca = ia >= 0 ? contraction[ia] : 0.0;
  const double cb = ib >= 0 ? contraction[ib] : 0.0;
  const double c = 0.5 * (ca + cb);
  if (sp.fibre_share.empty() || sp.fibre_share[j] < 0) return sp.rest_m[j] * (1.0 - c);
  const double fibre = std::max(0.2, 1.0 - c), cross = std::max(0.2, 1.0 - sp.cross_fibre[j] * c);
  const double fibre2 = fibre * fibre, cross2 = cross * cross, normal2 = 1.0 / (fibre2 * cross2);
  const double pulled = fibre * std::max(0.2, 1.0 - sp.fibre_tension * c);
  const double sheet = std::max(0.0, 1.0 - sp.fibre_share[j] - sp.normal_share[j]);  // Cross-fibre, in the wall.
  return sp.rest_m[j] * std::sqrt(1.0 + sp.fibre_share[j] * (pulled * pulled - 1.0) + sheet * (cross2 - 1.0) +
                                  sp.normal_share[j] * (normal2 - 1.0));
}

/// Rest volume of the volume constraint at time t: V0(t) = V0 (1 + amplitude phi(t - delay))
/// when the body has a volume drive (lungs inflating), else V0. Every solver's volume term
/// uses it in place of rest_m3. unit: m^3
inline double driven_rest_volume(const Model& model, double t_s) {
  const VolumeConstraint& vol = model.volume;
  if (vol.drive.waveform == Waveform::kNone) return vol.rest_m3;
  return vol.rest_m3 * (1.0 + vol.drive.amplitude * activation(vol.drive, t_s, model.ramp_s, vol.beat_boundaries));
}

/// Force on every particle at positions x, velocities v and time t (regions' contraction
/// already in state.region_contraction): springs with isotropic stiffness-proportional
/// damping c (v_b - v_a), c = k damping_s, the
/// volume pressure, active pokes and grabs. Gravity and drag are not included (they act on
/// velocities directly). Deterministic: accumulated in spring order. unit: N
void internal_and_scripted_forces(const Model& model, const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v,
                                  double t_s, State& state, Eigen::Matrix3Xd& force);

}  // namespace systole::sim
