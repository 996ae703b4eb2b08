#pragma once
// A zero-length attachment of a particle to a target position, per axis: C = x - target
// (Macklin et al. 2016, eq. 18 with the target's inverse mass 0). How training couples a
// body to key-frame motion; its multiplier / h^2 is the force the coupling exerts.

#include <Eigen/Core>

namespace systole::sim {

/// One projection of C = x - target for a particle of inverse mass w (1/kg) with
/// alpha_tilde = compliance / h^2 (m/(N s^2)): dlambda = -C / (w + alpha_tilde), x += w dlambda.
/// Returns dlambda (N s^2); a pinned particle (w = 0) is not moved and returns 0.
inline Eigen::Vector3d solve_attachment(Eigen::Ref<Eigen::Vector3d> x, const Eigen::Vector3d& target, double w,
                                        double alpha_tilde) {
  if (w == 0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d dlambda = -(x - target) / (w + alpha_tilde);
  x += w * dlambda;
  return dlambda;
}

}  // namespace systole::sim
