#pragma once
// A zero-length attachment of a particle to a target position, per axis: C = x - target
// (Macklin et al. 2016, eq. 18 with the target's inverse mass 0). How training couples a
// body to key-frame motion; its multiplier / h^2 is the force the coupling exerts.

#include <Eigen/Core>

#include "sim/reduced.h"

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

/// The same for surface point v embedded in the body (sim/reduced.h): C = sum_k w_k x_k +
/// offset - target, gradient w_k on corner k, so dlambda = -C / (sum_k w_k^2 w_inv_k +
/// alpha_tilde) and corner k moves by w_inv_k w_k dlambda. Adds w_k dlambda to corner k's
/// column of `lambda`: the coupling's force on each particle is then lambda / h^2.
inline void solve_embedded_attachment(Eigen::Matrix3Xd& x, const Embedding& e, int v, const Eigen::Vector3d& target,
                                      const Eigen::VectorXd& inverse_mass, double alpha_tilde, Eigen::Matrix3Xd& lambda) {
  Eigen::Vector3d p = e.offset.cols() ? Eigen::Vector3d(e.offset.col(v)) : Eigen::Vector3d::Zero();
  double denominator = alpha_tilde;
  for (int k = 0; k < 8; ++k) {
    const double w = e.weight(k, v);
    p += w * x.col(e.node(k, v));
    denominator += w * w * inverse_mass[e.node(k, v)];
  }
  if (denominator <= alpha_tilde) return;  // Every corner pinned (or weightless): nothing moves.
  const Eigen::Vector3d dlambda = -(p - target) / denominator;
  for (int k = 0; k < 8; ++k) {
    const int i = e.node(k, v);
    const double w = e.weight(k, v);
    x.col(i) += inverse_mass[i] * w * dlambda;
    lambda.col(i) += w * dlambda;
  }
}

}  // namespace systole::sim
