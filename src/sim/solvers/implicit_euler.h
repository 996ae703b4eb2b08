#pragma once
// Linearized backward Euler: Baraff & Witkin, "Large Steps in Cloth Simulation" (SIGGRAPH
// 1998), §2.2 eq. 6, multiplied through by M so the system is symmetric (their §5.1):
//
//   (M - h df/dv - h^2 df/dx) dv = h (f(x0, v0) + h df/dx v0),   v1 = v0 + dv,  x1 = x0 + h v1.
//
// One sparse solve per substep (Eigen's ConjugateGradient, Jacobi-preconditioned) buys
// stability at steps where the explicit solver needs dt < 2 / omega_max: stiff springs and
// a stiff volume stay bounded at a frame-sized step. The price is numerical damping that
// grows with h (backward Euler loses energy at rate ~ h omega^2), so a large step looks
// softer and slower to ring, never explosive.
//
// The volume term's stiffness k_V grad V grad V^T is dense but rank one: it is kept exact
// with the Sherman-Morrison formula (two CG solves on the sparse part) rather than treated
// explicitly, because an explicit pressure is exactly what limits the explicit solver's
// step with a stiff bulk modulus.

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances `state` by dt_s in model.substeps substeps of linearized backward Euler.
void implicit_step(const Model& model, State& state, double dt_s);

/// One damped spring's force and Jacobians (Baraff & Witkin 1998, §4 with C = |xb - xa| - L).
struct SpringLinearization {
  Eigen::Vector3d force_a_N = Eigen::Vector3d::Zero();  ///< Force on a; b gets its opposite. unit: N
  /// df_a/dx_b = -df_a/dx_a = df_b/dx_a: the material term k n n^T plus the geometric term
  /// k max(0, 1 - L/l) (I - n n^T), clamped at 0 for a compressed spring so every block is
  /// positive semidefinite and the system stays SPD for CG (Choi & Ko, "Stable but
  /// Responsive Cloth", SIGGRAPH 2002, §5). unit: N/m
  Eigen::Matrix3d stiffness_N_per_m = Eigen::Matrix3d::Zero();
  /// df_a/dv_b = c I of the isotropic damper (sim/forces.h): constant, so the system's
  /// damping part is exact at any step. unit: N s/m
  Eigen::Matrix3d damping_N_s_per_m = Eigen::Matrix3d::Zero();
};

/// Linearizes the spring from a to b. Inputs: d = xb - xa (unit: m), w = vb - va (unit: m/s),
/// stiffness k (unit: N/m), damping c = k * damping_s (unit: N s/m), rest length (unit: m).
/// A spring shorter than 1e-12 m has no direction and gives zeros (as forces.cpp).
SpringLinearization linearize_spring(const Eigen::Vector3d& d_m, const Eigen::Vector3d& w_m_per_s, double k_N_per_m,
                                     double c_N_s_per_m, double rest_m);

/// The solution of (A + u u^T) x = b from y = A^-1 b and z = A^-1 u (Sherman & Morrison,
/// 1950): x = y - z (u.y) / (1 + u.z). Overwrites y with x. A is SPD, so 1 + u.z >= 1.
void sherman_morrison_update(Eigen::VectorXd& y, const Eigen::VectorXd& z, const Eigen::VectorXd& u);

/// Relative residual |A dv - b| / |b| at which CG stops. unit: 1
inline constexpr double kImplicitCgTolerance = 1e-6;
/// CG iteration cap per solve; a solve that hits it counts as unconverged. unit: 1
inline constexpr int kImplicitCgMaxIterations = 1000;

using ImplicitCg = Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                                            Eigen::DiagonalPreconditioner<double>>;

/// What the implicit solver keeps between steps (owned by State::implicit): the matrix with
/// its pattern built once, where each 3x3 block's values live, work vectors and the solver.
struct ImplicitCache : SolverCache {
  int particles = 0;
  int springs = 0;
  Eigen::SparseMatrix<double> matrix;  ///< M - h df/dv - h^2 df/dx, pinned rows identity. unit: kg
  /// Value index of row 0 of each block column: entry (r, c) of a block is at slot[c] + r.
  std::vector<int> diagonal_slot;      ///< 3 per particle.
  std::vector<int> ab_slot, ba_slot;   ///< 3 per spring, for blocks (a, b) and (b, a).
  Eigen::VectorXd rhs;                 ///< h (f0 + h df/dx v0). unit: N s
  Eigen::VectorXd dv;                  ///< The velocity change. unit: m/s
  Eigen::VectorXd u;                   ///< h sqrt(k_V) grad V, the volume term's rank-1 factor. unit: kg^(1/2)
  Eigen::VectorXd z;                   ///< A^-1 u. unit: kg^(-1/2)
  ImplicitCg cg;

  // Numerical health, counted over the cache's life.
  long solves = 0;
  long cg_iterations = 0;             ///< Summed over solves. unit: 1
  int last_cg_iterations = 0;         ///< Of the last substep's velocity solve. unit: 1
  long unconverged_solves = 0;        ///< Solves that hit kImplicitCgMaxIterations.

  ImplicitCache() = default;
  /// Copies everything but the solver, which holds a reference to its matrix and is
  /// re-pointed (compute) every substep anyway.
  ImplicitCache(const ImplicitCache& other);
  ImplicitCache& operator=(const ImplicitCache&) = delete;
  std::unique_ptr<SolverCache> clone() const override;
};

/// Builds the sparsity pattern (a 3x3 block per particle and per spring pair, both ways)
/// and the slot table for `model`.
std::unique_ptr<ImplicitCache> build_implicit_cache(const Model& model);

}  // namespace systole::sim
