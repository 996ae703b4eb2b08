#include "sim/solvers/projective.h"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "common/error.h"
#include "sim/constraints/volume.h"
#include "sim/forces.h"
#include "sim/interactions.h"
#include "sim/solvers/substep.h"

namespace systole::sim {
namespace {

/// Per free particle one row: x, y, z of a right-hand side (and of the volume gradient).
/// Row-major, so the triangular solves below update a particle's columns together.
using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Ldlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

/// Solves A X = B in place for the factorized A = P^T L D L^T P, all of B's columns in one
/// pass over L: Eigen's own solve walks L once per column, which made the back-substitution
/// most of a step's cost. L is unit lower triangular in compressed columns without its
/// diagonal (SimplicialLDLT's storage). Each row is held as four lanes (the last ones
/// padding), so a row update is two vector instructions rather than three scalar ones; every
/// lane's arithmetic, and its order, is the scalar loop's, bit for bit.
template <int Columns>
void solve_in_place(const Ldlt& ldlt, Rows& b) {
  static_assert(Columns <= 4);
  using Lanes = Eigen::Array4d;
  const Eigen::Index n = b.rows();
  thread_local std::vector<Lanes> work;  // One allocation per thread, not per solve.
  work.assign(static_cast<std::size_t>(n), Lanes::Zero());
  const auto& p = ldlt.permutationP();
  for (Eigen::Index i = 0; i < n; ++i) {
    Lanes& w = work[static_cast<std::size_t>(p.indices()[i])];
    for (int c = 0; c < Columns; ++c) w[c] = b(i, c);
  }
  const Eigen::SparseMatrix<double>& l = ldlt.matrixL().nestedExpression();
  const int* start = l.outerIndexPtr();
  const int* row = l.innerIndexPtr();
  const double* value = l.valuePtr();
  // Row j in registers: L is strictly lower, so the rows a column updates are never j itself.
  for (Eigen::Index j = 0; j < n; ++j) {
    const Lanes wj = work[static_cast<std::size_t>(j)];
    for (int q = start[j]; q < start[j + 1]; ++q) work[static_cast<std::size_t>(row[q])] -= value[q] * wj;
  }
  const auto& d = ldlt.vectorD();
  for (Eigen::Index j = 0; j < n; ++j) work[static_cast<std::size_t>(j)] /= d[j];
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    Lanes wj = work[static_cast<std::size_t>(j)];
    for (int q = start[j]; q < start[j + 1]; ++q) wj -= value[q] * work[static_cast<std::size_t>(row[q])];
    work[static_cast<std::size_t>(j)] = wj;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const Lanes& w = work[static_cast<std::size_t>(p.indices()[i])];
    for (int c = 0; c < Columns; ++c) b(i, c) = w[c];
  }
}

/// A factorized system matrix for one g = h (backward Euler) or 2h/3 (BDF2) and one set of
/// active grabs.
struct Factor {
  double gamma_s = 0;               ///< unit: s
  std::vector<bool> grabs_active;   ///< Which grabs' springs are in the matrix.
  std::unique_ptr<Ldlt> ldlt;
  /// Per spring: c_e/g, as the matrix has it (each step's right-hand side needs it again).
  /// unit: N/m
  std::vector<double> damping_over_gamma;

  bool matches(double gamma, const std::vector<bool>& grabs) const {
    return ldlt && gamma_s == gamma && grabs_active == grabs;
  }
};

/// The volume term's Hessian k_V g g^T, with g = grad V at a recent step's start (free
/// rows), and z = A^-1 g for the Sherman-Morrison formula. Refreshed every
/// kVolumeHessianSteps steps (and with the factor): a three-column solve, which at one
/// iteration a step would otherwise double the step's cost, while g turns by a fraction of
/// a percent per step as an organ beats.
struct VolumeHessian {
  Rows g, z;
  double g_dot_z = 0;
  double gamma_s = 0;               ///< The factor z was solved with: its g and grabs. unit: s
  std::vector<bool> grabs_active;
  long step = -1;                   ///< The step it was taken at.
};

inline constexpr long kVolumeHessianSteps = 4;

/// What the solver keeps between steps: the free particles' numbering, the two
/// factorizations and BDF2's history. Eigen's factorizations do not copy, so a clone keeps
/// the history and refactorizes on its first step, which gives bit-identical factors.
struct ProjectiveCache : SolverCache {
  int particles = 0;
  int springs = 0;
  double material = 0;  ///< material_fingerprint of the model the factors are of.
  std::vector<int> free_index;  ///< Per particle: its row in the system, or -1 (pinned).
  std::vector<int> free_particles;
  /// Per spring: k_e = 1 / compliance, worked out once (a division a spring a step was a
  /// tenth of the step). unit: N/m
  std::vector<double> stiffness;
  Factor backward_euler, bdf2;
  VolumeHessian volume;
  long steps = 0;  ///< Steps taken, counting from the cache's creation.

  // BDF2's history: the state one step before the current one.
  Eigen::Matrix3Xd x_old, v_old;
  double history_time_s = std::numeric_limits<double>::quiet_NaN();  ///< Time of x_old. unit: s
  double history_step_s = 0;                                         ///< The step taken from it. unit: s

  std::unique_ptr<SolverCache> clone() const override {
    auto copy = std::make_unique<ProjectiveCache>();
    copy->particles = particles;
    copy->springs = springs;
    copy->material = material;
    copy->free_index = free_index;
    copy->free_particles = free_particles;
    copy->stiffness = stiffness;
    copy->x_old = x_old;
    copy->v_old = v_old;
    copy->history_time_s = history_time_s;
    copy->history_step_s = history_step_s;
    copy->volume = volume;  // Valid with the factors the copy rebuilds bit for bit.
    copy->steps = steps;
    return copy;
  }
};

/// What the system matrix is made of, in one number: a State stepped by another model of
/// the same size (training tries other stiffnesses on copies) must not reuse its factors.
double material_fingerprint(const Model& model) {
  double sum = model.drag_per_s;
  const Springs& sp = model.springs;
  for (int j = 0; j < sp.size(); ++j) sum += (j + 1) * (sp.compliance_m_per_N[j] + 1e3 * sp.damping_s[j]);
  for (Eigen::Index i = 0; i < model.inverse_mass.size(); ++i) sum += (i + 1) * model.inverse_mass[i];
  return sum;
}

ProjectiveCache& cache_for(const Model& model, State& s) {
  ProjectiveCache* c = s.solver_cache.get<ProjectiveCache>();
  const double material = material_fingerprint(model);
  if (c != nullptr && c->particles == model.particle_count() && c->springs == model.springs.size() &&
      c->material == material) {
    return *c;
  }
  auto fresh = std::make_unique<ProjectiveCache>();
  fresh->particles = model.particle_count();
  fresh->springs = model.springs.size();
  fresh->material = material;
  fresh->free_index.assign(model.particle_count(), -1);
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.inverse_mass[i] == 0) continue;
    fresh->free_index[i] = static_cast<int>(fresh->free_particles.size());
    fresh->free_particles.push_back(i);
  }
  fresh->stiffness.resize(static_cast<std::size_t>(model.springs.size()));
  for (int j = 0; j < model.springs.size(); ++j) fresh->stiffness[static_cast<std::size_t>(j)] = 1.0 / model.springs.compliance_m_per_N[j];
  c = fresh.get();
  s.solver_cache.reset(std::move(fresh));
  return *c;
}

std::vector<bool> active_grabs(const Model& model, double t_s) {
  std::vector<bool> active;
  for (const Grab& g : model.grabs) active.push_back(grab_active(g, t_s));
  return active;
}

/// A = M (1/g^2 + drag/g) + sum_e (k_e + c_e/g) G_e^T G_e + k_grab on grabbed particles,
/// over the free particles (a pinned end's terms move to the right-hand side).
void factorize(const Model& model, const ProjectiveCache& c, double gamma, const std::vector<bool>& grabs,
               Factor& out) {
  const int n = static_cast<int>(c.free_particles.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n) + 4 * static_cast<std::size_t>(model.springs.size()));
  for (int r = 0; r < n; ++r) {
    const double m = 1.0 / model.inverse_mass[c.free_particles[r]];
    entries.emplace_back(r, r, m * (1.0 / (gamma * gamma) + model.drag_per_s / gamma));
  }
  const Springs& sp = model.springs;
  out.damping_over_gamma.resize(static_cast<std::size_t>(sp.size()));
  for (int j = 0; j < sp.size(); ++j) {
    const double k = c.stiffness[static_cast<std::size_t>(j)];
    const double c_over_g = k * sp.damping_s[j] / gamma;
    out.damping_over_gamma[static_cast<std::size_t>(j)] = c_over_g;
    const double weight = k + c_over_g;
    const int ra = c.free_index[sp.a[j]], rb = c.free_index[sp.b[j]];
    if (ra >= 0) entries.emplace_back(ra, ra, weight);
    if (rb >= 0) entries.emplace_back(rb, rb, weight);
    if (ra >= 0 && rb >= 0) {
      entries.emplace_back(ra, rb, -weight);
      entries.emplace_back(rb, ra, -weight);
    }
  }
  for (std::size_t g = 0; g < model.grabs.size(); ++g) {
    if (!grabs[g]) continue;
    for (int i : model.grabs[g].particles) {
      if (c.free_index[i] >= 0) entries.emplace_back(c.free_index[i], c.free_index[i], 1.0 / model.grabs[g].compliance_m_per_N);
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  out.ldlt = std::make_unique<Ldlt>(a);
  if (out.ldlt->info() != Eigen::Success) {
    throw Error(ExitCode::kInternal, "projective solver: the system matrix of '" + model.name + "' is not positive definite");
  }
  out.gamma_s = gamma;
  out.grabs_active = grabs;
}

/// One step's fixed quantities: g, x~ (every particle; pinned ones at their new place) and
/// the right-hand side's constant part, M x^/g^2 + drag M x~/g + f_ext + the dampers'
/// c/g G^T G x~ + the pinned ends' (k + c/g) x_pinned.
struct StepSetup {
  double gamma = 0;
  Eigen::Matrix3Xd x_tilde;   ///< unit: m
  Rows rhs;                   ///< Free particles' rows, 3 columns. unit: N
  /// Per spring: its driven rest length at the step's end, which every iteration of the step
  /// projects to (worked out once: it is most of a projection's cost). unit: m
  std::vector<double> rest_m;
};

StepSetup set_up(const Model& model, const State& s, const ProjectiveCache& c, const Factor& factor, bool bdf2,
                 double t_end, const Eigen::Matrix3Xd& x_new_pinned) {
  StepSetup out;
  Eigen::Matrix3Xd v_bar;
  out.gamma = factor.gamma_s;
  if (bdf2) {
    out.x_tilde = (4.0 * s.x - c.x_old) / 3.0;
    v_bar = (4.0 * s.v - c.v_old) / 3.0;
  } else {
    out.x_tilde = s.x;
    v_bar = s.v;
  }
  const double g = out.gamma;
  const int n = static_cast<int>(c.free_particles.size());
  // Pinned particles sit where they will be at the step's end; their x~ is that place too,
  // so their dampers see them still (as the other solvers do).
  for (int i = 0; i < model.particle_count(); ++i) {
    if (c.free_index[i] < 0) out.x_tilde.col(i) = x_new_pinned.col(i);
  }
  Eigen::Matrix3Xd f_ext = Eigen::Matrix3Xd::Zero(3, model.pokes.empty() && model.grabs.empty() ? 0 : model.particle_count());
  for_each_poke(model, s.time_s, [&](int i, double factor, const Eigen::Vector3d& force_N) { f_ext.col(i) += factor * force_N; });
  for_each_grab(model, t_end, [&](int i, const Eigen::Vector3d& target_m, double compliance_m_per_N) {
    f_ext.col(i) += (1.0 / compliance_m_per_N) * target_m;
  });
  out.rest_m.resize(static_cast<std::size_t>(model.springs.size()));
  for (int j = 0; j < model.springs.size(); ++j) {
    out.rest_m[static_cast<std::size_t>(j)] = driven_rest_length(model.springs, j, s.region_contraction);
  }
  out.rhs.resize(n, 3);
  for (int r = 0; r < n; ++r) {
    const int i = c.free_particles[r];
    const double m = 1.0 / model.inverse_mass[i];
    const Eigen::Vector3d x_hat = out.x_tilde.col(i) + g * v_bar.col(i);
    out.rhs.row(r) = (m * (x_hat / (g * g) + model.drag_per_s * out.x_tilde.col(i) / g + model.gravity)).transpose();
    if (f_ext.cols() > 0) out.rhs.row(r) += f_ext.col(i).transpose();
  }
  const Springs& sp = model.springs;
  for (int j = 0; j < sp.size(); ++j) {
    const int a = sp.a[j], b = sp.b[j];
    const double k = c.stiffness[static_cast<std::size_t>(j)];
    const double c_over_g = factor.damping_over_gamma[static_cast<std::size_t>(j)];
    const int ra = c.free_index[a], rb = c.free_index[b];
    const Eigen::Vector3d damping = c_over_g * (out.x_tilde.col(a) - out.x_tilde.col(b));
    if (ra >= 0) out.rhs.row(ra) += damping.transpose();
    if (rb >= 0) out.rhs.row(rb) -= damping.transpose();
    if (ra >= 0 && rb < 0) out.rhs.row(ra) += ((k + c_over_g) * x_new_pinned.col(b)).transpose();
    if (rb >= 0 && ra < 0) out.rhs.row(rb) += ((k + c_over_g) * x_new_pinned.col(a)).transpose();
  }
  return out;
}

/// The springs' projections: adds k_e G_e^T p_e to the right-hand side, p_e the current
/// edge scaled to its driven rest length.
void add_projections(const Model& model, const StepSetup& setup, const ProjectiveCache& c, const Eigen::Matrix3Xd& x,
                     Rows& rhs) {
  const Springs& sp = model.springs;
  for (int j = 0; j < sp.size(); ++j) {
    const int a = sp.a[j], b = sp.b[j];
    const Eigen::Vector3d d = x.col(b) - x.col(a);
    const double len = d.norm();
    if (len < 1e-12) continue;  // No direction: the spring pulls nowhere this iteration.
    const Eigen::Vector3d p = (setup.rest_m[static_cast<std::size_t>(j)] / (len * sp.compliance_m_per_N[j])) * d;
    if (c.free_index[a] >= 0) rhs.row(c.free_index[a]) -= p.transpose();
    if (c.free_index[b] >= 0) rhs.row(c.free_index[b]) += p.transpose();
  }
}

/// Brings c.volume up to date for this step with `factor` (see VolumeHessian).
void refresh_volume_hessian(const Model& model, ProjectiveCache& c, const Factor& factor, const Eigen::Matrix3Xd& x,
                            Eigen::Matrix3Xd& gradient) {
  VolumeHessian& v = c.volume;
  const bool fresh = v.step >= 0 && factor.matches(v.gamma_s, v.grabs_active) && c.steps - v.step < kVolumeHessianSteps;
  if (!model.volume.enabled || fresh) return;
  volume_and_gradient(x, model.volume.triangles, gradient);
  const int n = static_cast<int>(c.free_particles.size());
  v.g.resize(n, 3);
  for (int r = 0; r < n; ++r) v.g.row(r) = gradient.col(c.free_particles[r]).transpose();
  v.z = v.g;
  solve_in_place<3>(*factor.ldlt, v.z);
  v.g_dot_z = v.g.cwiseProduct(v.z).sum();
  v.gamma_s = factor.gamma_s;
  v.grabs_active = factor.grabs_active;
  v.step = c.steps;
}

/// The ventricles' blood for one step (sim/circulation.h): per chamber whose valves are both
/// shut, z = A^-1 f with f the blood's push at unit pressure at the step's start (free rows;
/// the volume's gradient, but for the share the chordae carry to the wall): the direction in
/// which the pressure moves the body to hold the chamber's volume.
struct HeldChambers {
  std::vector<int> chamber;
  std::vector<Rows> z;
};

HeldChambers hold_chambers(const Model& model, const State& s, const ProjectiveCache& c, const Factor& factor) {
  HeldChambers held;
  const int n = static_cast<int>(c.free_particles.size());
  Eigen::Matrix3Xd gradient;
  for (std::size_t k = 0; k < s.chambers.size(); ++k) {
    if (!isovolumic(s.chambers[k].phase)) continue;
    // The blood's push at unit pressure: the volume's gradient, but for the share of the
    // shut inflow valve's load that its chordae carry to the wall.
    gradient.setZero(3, s.x.cols());
    add_pressure_load(model.circulation.chambers[k], s.chambers[k].phase, s.x, 1.0, gradient);
    Rows g(n, 3);
    for (int r = 0; r < n; ++r) g.row(r) = gradient.col(c.free_particles[r]).transpose();
    solve_in_place<3>(*factor.ldlt, g);
    held.chamber.push_back(static_cast<int>(k));
    held.z.push_back(std::move(g));
  }
  return held;
}

/// The pressure a chamber's lining is pushed out with: the afterload while it ejects, the
/// filling pressure while it fills; none while its volume is held (the multiplier is). unit: Pa
double load_Pa(const Circulation& circulation, const Chamber& chamber, const ChamberState& state) {
  const ChamberPhase phase = state.phase;
  if (phase == ChamberPhase::kEjection) return chamber.afterload_Pa + chamber.arterial_elastance_Pa_per_m3 * (state.shut_m3 - state.volume_m3);
  if (phase == ChamberPhase::kFilling) return circulation.filling_Pa;
  return 0;
}

/// The held chambers' volumes, linearized at the iterate: y + sum_j z_j mu_j with
/// g_i . (y + sum_j z_j mu_j - x) = V_shut,i - V_i(x). The multiplier mu_i pushes the lining
/// along grad V_i: it is the chamber's pressure. Adds the push to the solved positions `y`
/// (`rhs`, rows of the free particles) and keeps each multiplier as its chamber's pressure.
void hold_chambers(const ProjectiveCache& c, const HeldChambers& held, const std::vector<Eigen::Matrix3Xd>& chamber_gradient,
                   const std::vector<double>& chamber_m3, const Eigen::Matrix3Xd& x, State& s, Rows& rhs) {
  const int n = static_cast<int>(c.free_particles.size());
  const Eigen::Index m = static_cast<Eigen::Index>(held.chamber.size());
  Eigen::MatrixXd coupling(m, m);
  Eigen::VectorXd residual(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const int k = held.chamber[static_cast<std::size_t>(i)];
    const Eigen::Matrix3Xd& g = chamber_gradient[static_cast<std::size_t>(k)];
    double g_dot_step = 0;
    Eigen::VectorXd g_dot_z = Eigen::VectorXd::Zero(m);
    for (int r = 0; r < n; ++r) {
      const int p = c.free_particles[r];
      const Eigen::Vector3d gp = g.col(p);
      g_dot_step += gp.dot(rhs.row(r).transpose() - x.col(p));
      for (Eigen::Index j = 0; j < m; ++j) g_dot_z[j] += gp.dot(held.z[static_cast<std::size_t>(j)].row(r).transpose());
    }
    coupling.row(i) = g_dot_z.transpose();
    residual[i] = s.chambers[static_cast<std::size_t>(k)].shut_m3 - chamber_m3[static_cast<std::size_t>(k)] - g_dot_step;
  }
  const Eigen::VectorXd mu = coupling.partialPivLu().solve(residual);
  for (Eigen::Index j = 0; j < m; ++j) {
    rhs += mu[j] * held.z[static_cast<std::size_t>(j)];
    s.chambers[static_cast<std::size_t>(held.chamber[static_cast<std::size_t>(j)])].pressure_Pa = mu[j];
  }
}

/// One local/global iteration from the iterate x (every particle; pinned ones already at
/// their new place): writes the new free positions into x.
void iterate(const Model& model, State& s, const ProjectiveCache& c, const Factor& factor, const StepSetup& setup,
             const VolumeHessian& hessian, const HeldChambers& held, double t_end, Eigen::Matrix3Xd& x) {
  const int n = static_cast<int>(c.free_particles.size());
  const bool volume = model.volume.enabled;
  Rows rhs = setup.rhs;
  add_projections(model, setup, c, x, rhs);
  // The chambers at the iterate: the loads on the filling and ejecting ones; the volumes and
  // gradients of the held ones.
  const std::size_t chambers = s.chambers.size();
  std::vector<double> chamber_m3(chambers);
  std::vector<Eigen::Matrix3Xd> chamber_gradient(chambers);
  Eigen::Matrix3Xd load_force;
  for (std::size_t k = 0; k < chambers; ++k) {
    const Chamber& chamber = model.circulation.chambers[k];
    if (isovolumic(s.chambers[k].phase)) {
      chamber_m3[k] = chamber_volume(chamber, x, chamber_gradient[k]);
      continue;
    }
    const double load = s.chambers[k].pressure_Pa;  // The step's load (one_step).
    if (load == 0) continue;
    if (load_force.cols() == 0) load_force.setZero(3, x.cols());
    add_pressure_load(chamber, s.chambers[k].phase, x, load, load_force);
  }
  if (load_force.cols() > 0) {
    for (int r = 0; r < n; ++r) rhs.row(r) += load_force.col(c.free_particles[r]).transpose();
  }
  if (volume) {
    // A quasi-Newton step on the volume energy k_V/2 (V - V0(t))^2 with the Hessian
    // k_V g0 g0^T of the step's start (VolumeHessian): (A + k_V g0 g0^T) y = rhs +
    // k_V g0 (g0.x) - k_V g (V(x) - V0(t)), g = grad V at the iterate x. Its fixed point is
    // the exact minimizer; g0 only sets how fast the iterations approach it.
    const double v = volume_and_gradient(x, model.volume.triangles, s.volume_gradient);
    const double k_v = 1.0 / model.volume.compliance_m5_per_N;
    const double excess = v - driven_rest_volume(model, t_end);
    double g0_dot_x = 0;
    for (int r = 0; r < n; ++r) {
      const int i = c.free_particles[r];
      g0_dot_x += hessian.g.row(r).dot(x.col(i).transpose());
      rhs.row(r) -= (k_v * excess) * s.volume_gradient.col(i).transpose();
    }
    rhs += (k_v * g0_dot_x) * hessian.g;
  }
  solve_in_place<3>(*factor.ldlt, rhs);
  if (volume) {
    // Sherman-Morrison: (A + k g0 g0^T)^-1 b = y - z k (g0.y) / (1 + k g0.z), y = A^-1 b.
    const double k_v = 1.0 / model.volume.compliance_m5_per_N;
    rhs -= (k_v * hessian.g.cwiseProduct(rhs).sum() / (1.0 + k_v * hessian.g_dot_z)) * hessian.z;
  }
  if (!held.chamber.empty()) hold_chambers(c, held, chamber_gradient, chamber_m3, x, s, rhs);
  for (int r = 0; r < n; ++r) x.col(c.free_particles[r]) = rhs.row(r).transpose();
}

void one_step(const Model& model, State& s, ProjectiveCache& c, double h) {
  const double t_end = s.time_s + h;
  update_contractions(model, s, t_end);
  const bool bdf2 = c.history_step_s == h && std::abs(c.history_time_s + h - s.time_s) <= 1e-9 * h;
  Eigen::Matrix3Xd x = s.x;
  move_kinematic_regions(model, t_end, x);
  const double gamma = bdf2 ? 2.0 * h / 3.0 : h;
  Factor& factor = bdf2 ? c.bdf2 : c.backward_euler;
  const std::vector<bool> grabs = active_grabs(model, t_end);
  if (!factor.matches(gamma, grabs)) factorize(model, c, gamma, grabs, factor);
  const StepSetup setup = set_up(model, s, c, factor, bdf2, t_end, x);
  // Start from where the old velocity carries the body: the springs' directions there are
  // close to the solution's.
  for (int i : c.free_particles) x.col(i) = s.x.col(i) + h * s.v.col(i);
  refresh_volume_hessian(model, c, factor, s.x, s.volume_gradient);
  const HeldChambers held = hold_chambers(model, s, c, factor);
  for (std::size_t k = 0; k < s.chambers.size(); ++k) {
    if (!isovolumic(s.chambers[k].phase)) s.chambers[k].pressure_Pa = load_Pa(model.circulation, model.circulation.chambers[k], s.chambers[k]);
  }
  for (int k = 0; k < model.iterations; ++k) iterate(model, s, c, factor, setup, c.volume, held, t_end, x);
  resolve_floor_contact(model, x);
  c.x_old = s.x;
  c.v_old = s.v;
  c.history_time_s = s.time_s;
  c.history_step_s = h;
  ++c.steps;
  for (int i : c.free_particles) s.v.col(i) = (x.col(i) - setup.x_tilde.col(i)) / setup.gamma;
  s.x_prev = s.x;
  s.x = x;
  s.time_s = t_end;
  if (model.circulation.enabled()) advance_phases(model.circulation, s.x, h, s.chambers);
}

}  // namespace

void projective_step(const Model& model, State& s, double dt_s) {
  ProjectiveCache& c = cache_for(model, s);
  const double h = dt_s / model.substeps;
  for (int sub = 0; sub < model.substeps; ++sub) one_step(model, s, c, h);
}

void projective_restart(State& s) {
  if (ProjectiveCache* c = s.solver_cache.get<ProjectiveCache>()) c->history_time_s = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace systole::sim
