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

/// Every surface point embedded in the body (sim/reduced.h) at once: point v's constraint
/// C_v = sum_k w_k x_k + offset - target_v, gradient w_k on corner k, asks dlambda_v =
/// -C_v / (sum_k w_k^2 w_inv_k + alpha_tilde) and moves corner k by w_inv_k w_k dlambda_v.
/// All points are projected from the same positions and a corner moves by the mean of what
/// its points ask, each weighted by its hold on the corner w_k (Jacobi with constraint
/// averaging, Macklin et al. 2014, sec. 4.2; a point at the far side of a cell asks next to
/// nothing of a corner and does not dilute what the near points ask). A render surface has
/// tens of points per cell: projected one after another (Gauss-Seidel), each point drags the
/// shared corners its own way and the last ones undo the first (the anatomical heart tied
/// to its own motion stayed 140 % of that motion away). `lambda` gains each corner's
/// averaged share, so lambda / h^2 stays the force the coupling exerts on each particle.
/// Sequential sums: the same at any thread count. `pull` (per corner, sum of w_k w_k dlambda_v)
/// and `hold` (per corner, sum of w_k) are scratch of x's size, so a step does not allocate.
inline void solve_embedded_attachments(Eigen::Matrix3Xd& x, const Embedding& e, const Eigen::Matrix3Xd& targets,
                                       const Eigen::VectorXd& inverse_mass, double alpha_tilde,
                                       Eigen::Matrix3Xd& lambda, Eigen::Matrix3Xd& pull, Eigen::VectorXd& hold) {
  pull.setZero(3, x.cols());  // Sized once (State keeps them); zeroed every call.
  hold.setZero(x.cols());
  for (int v = 0; v < e.vertex_count(); ++v) {
    Eigen::Vector3d p = e.offset.cols() ? Eigen::Vector3d(e.offset.col(v)) : Eigen::Vector3d::Zero();
    double denominator = alpha_tilde;
    for (int k = 0; k < 8; ++k) {
      const double w = e.weight(k, v);
      p += w * x.col(e.node(k, v));
      denominator += w * w * inverse_mass[e.node(k, v)];
    }
    if (denominator <= alpha_tilde) continue;  // Every corner pinned (or weightless): nothing moves.
    const Eigen::Vector3d dlambda = -(p - targets.col(v)) / denominator;
    for (int k = 0; k < 8; ++k) {
      const double w = e.weight(k, v);
      pull.col(e.node(k, v)) += w * w * dlambda;
      hold[e.node(k, v)] += w;
    }
  }
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (hold[i] == 0) continue;
    const Eigen::Vector3d share = pull.col(i) / hold[i];
    x.col(i) += inverse_mass[i] * share;
    lambda.col(i) += share;
  }
}

}  // namespace systole::sim
