#pragma once
// The enclosed volume of a closed surface and its gradient, and the global volume
// constraint C = V(x) - V0 in XPBD form (Müller et al., "Position Based Dynamics", 2007,
// §4.4; Macklin et al. 2016, eq. 18): one multiplier for the whole surface. Every solver's
// volume term uses these: XPBD projects, the explicit and implicit solvers take the
// pressure force -(V - V0) / compliance * dV/dx.

#include <Eigen/Core>
#include <vector>

namespace systole::sim {

/// Enclosed volume of a closed, outward-oriented triangle surface (divergence theorem:
/// V = sum over triangles of p0 . (p1 x p2) / 6). unit: m^3
double enclosed_volume(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles);

/// The enclosed volume (returned, m^3) and its gradient dV/dx into `gradient` (3 x particles,
/// m^2): dV/dp0 = (p1 x p2) / 6 summed over the triangles at each corner.
double volume_and_gradient(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles,
                           Eigen::Matrix3Xd& gradient);

/// One XPBD projection of C = V - V0 with value `c` (m^3) and gradient `gradient` at x:
///   dlambda = (-C - alpha_tilde lambda) / (sum_i w_i |grad_i C|^2 + alpha_tilde),
///   x_i += w_i dlambda grad_i C.
/// Inputs: inverse masses w (1/kg), alpha_tilde = compliance / h^2 (m^5/(N s^2)), the
/// multiplier so far (N s^2/m^2). Returns dlambda; 0 (nothing moved) when nothing can move.
double solve_volume(Eigen::Matrix3Xd& x, const Eigen::VectorXd& w, const Eigen::Matrix3Xd& gradient, double c,
                    double alpha_tilde, double lambda);

}  // namespace systole::sim
