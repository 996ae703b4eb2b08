#include "sim/solvers/implicit_euler.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>

#include "sim/constraints/volume.h"
#include "sim/drive.h"
#include "sim/forces.h"
#include "sim/interactions.h"
#include "sim/solvers/substep.h"

namespace systole::sim {

ImplicitCache::ImplicitCache(const ImplicitCache& o)
    : particles(o.particles),
      springs(o.springs),
      matrix(o.matrix),
      diagonal_slot(o.diagonal_slot),
      ab_slot(o.ab_slot),
      ba_slot(o.ba_slot),
      rhs(o.rhs),
      dv(o.dv),
      u(o.u),
      z(o.z),
      solves(o.solves),
      cg_iterations(o.cg_iterations),
      last_cg_iterations(o.last_cg_iterations),
      unconverged_solves(o.unconverged_solves) {}

std::unique_ptr<SolverCache> ImplicitCache::clone() const { return std::make_unique<ImplicitCache>(*this); }

// ---------------------------------------------------------------------------------------
// Kernels.

SpringLinearization linearize_spring(const Eigen::Vector3d& d, const Eigen::Vector3d& w, double k, double c,
                                     double rest) {
  SpringLinearization out;
  const double len = d.norm();
  if (len < 1e-12) return out;
  const Eigen::Vector3d n = d / len;
  // The same expression as forces.cpp, so a body at rest feels exactly zero force.
  out.force_a_N = k * (len - rest) * n + c * w;
  const Eigen::Matrix3d nn = n * n.transpose();
  // d(k (l - L) n)/dx_b = k n n^T + k (l - L)/l (I - n n^T); the second (geometric) term
  // is negative for a compressed spring, which would make the system indefinite: clamp.
  const double geometric = k * std::max(0.0, 1.0 - rest / len);
  out.stiffness_N_per_m = k * nn + geometric * (Eigen::Matrix3d::Identity() - nn);
  out.damping_N_s_per_m = c * Eigen::Matrix3d::Identity();
  return out;
}

void sherman_morrison_update(Eigen::VectorXd& y, const Eigen::VectorXd& z, const Eigen::VectorXd& u) {
  const double scale = u.dot(y) / (1.0 + u.dot(z));
  y -= scale * z;
}

// ---------------------------------------------------------------------------------------
// Pattern and assembly.

namespace {

/// Index in `m`'s value array of entry (row, col), which must be in the pattern.
int value_index(const Eigen::SparseMatrix<double>& m, int row, int col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  assert(it != end && *it == row);
  return static_cast<int>(it - m.innerIndexPtr());
}

/// Adds the 3x3 block `b` at the block whose column starts are `slot[0..2]`.
inline void add_block(double* values, const int* slot, const Eigen::Matrix3d& b) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) values[slot[c] + r] += b(r, c);
  }
}

inline void add_identity(double* values, const int* slot, double s) {
  for (int c = 0; c < 3; ++c) values[slot[c] + c] += s;
}

}  // namespace

std::unique_ptr<ImplicitCache> build_implicit_cache(const Model& model) {
  auto cache = std::make_unique<ImplicitCache>();
  const Springs& sp = model.springs;
  const int n = model.particle_count();
  cache->particles = n;
  cache->springs = sp.size();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * (static_cast<std::size_t>(n) + 2 * static_cast<std::size_t>(sp.size())));
  auto block = [&](int p, int q) {
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) entries.emplace_back(3 * p + r, 3 * q + c, 0.0);
    }
  };
  for (int i = 0; i < n; ++i) block(i, i);
  for (int j = 0; j < sp.size(); ++j) {
    block(sp.a[j], sp.b[j]);
    block(sp.b[j], sp.a[j]);
  }
  cache->matrix.resize(3 * n, 3 * n);
  cache->matrix.setFromTriplets(entries.begin(), entries.end());  // Duplicate pairs share a block.
  cache->matrix.makeCompressed();
  auto slots = [&](int p, int q, std::vector<int>& out) {
    for (int c = 0; c < 3; ++c) out.push_back(value_index(cache->matrix, 3 * p, 3 * q + c));
  };
  cache->diagonal_slot.reserve(3 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) slots(i, i, cache->diagonal_slot);
  cache->ab_slot.reserve(3 * static_cast<std::size_t>(sp.size()));
  cache->ba_slot.reserve(3 * static_cast<std::size_t>(sp.size()));
  for (int j = 0; j < sp.size(); ++j) {
    slots(sp.a[j], sp.b[j], cache->ab_slot);
    slots(sp.b[j], sp.a[j], cache->ba_slot);
  }
  cache->rhs = Eigen::VectorXd::Zero(3 * n);
  cache->dv = Eigen::VectorXd::Zero(3 * n);
  cache->u = Eigen::VectorXd::Zero(model.volume.enabled ? 3 * n : 0);
  cache->z = Eigen::VectorXd::Zero(model.volume.enabled ? 3 * n : 0);
  return cache;
}

namespace {

ImplicitCache& cache_for(const Model& model, State& s) {
  ImplicitCache* c = s.solver_cache.get<ImplicitCache>();
  if (c == nullptr || c->particles != model.particle_count() || c->springs != model.springs.size()) {
    auto fresh = build_implicit_cache(model);
    c = fresh.get();
    s.solver_cache.reset(std::move(fresh));
  }
  return *c;
}

/// Writes M (identity for pinned particles), the springs' h df/dv + h^2 df/dx blocks and
/// the grabs' h^2 k I into the matrix, and h (f0 + h df/dx v0) plus gravity and pokes into
/// the right-hand side (Baraff & Witkin eq. 6 times M). Pinned particles' rows and columns
/// are eliminated: their dv is 0, so their blocks off the diagonal stay zero.
void assemble(const Model& model, State& s, ImplicitCache& c, double h, double t_start, double t_end) {
  const Springs& sp = model.springs;
  const Eigen::VectorXd& w = model.inverse_mass;
  double* values = c.matrix.valuePtr();
  std::fill(values, values + c.matrix.nonZeros(), 0.0);
  Eigen::Map<Eigen::Matrix3Xd> rhs(c.rhs.data(), 3, s.x.cols());
  const int n = model.particle_count();
  for (int i = 0; i < n; ++i) {
    if (w[i] == 0) {
      add_identity(values, &c.diagonal_slot[3 * i], 1.0);
      rhs.col(i).setZero();
    } else {
      add_identity(values, &c.diagonal_slot[3 * i], 1.0 / w[i]);
      rhs.col(i) = h / w[i] * model.gravity;
    }
  }
  const double h2 = h * h;
  for (int j = 0; j < sp.size(); ++j) {
    const int a = sp.a[j], b = sp.b[j];
    const double k = 1.0 / sp.compliance_m_per_N[j];
    const SpringLinearization lin =
        linearize_spring(s.x.col(b) - s.x.col(a), s.v.col(b) - s.v.col(a), k, k * sp.damping_s[j],
                         driven_rest_length(sp, j, s.region_contraction));
    // A_aa += B, A_bb += B, A_ab = A_ba -= B with B = h c I + h^2 K (units: kg).
    const Eigen::Matrix3d block = h * lin.damping_N_s_per_m + h2 * lin.stiffness_N_per_m;
    // h f_a + h^2 (df_a/dx_a v_a + df_a/dx_b v_b) = h f_a + h^2 K (v_b - v_a); b opposite.
    const Eigen::Vector3d impulse = h * lin.force_a_N + h2 * lin.stiffness_N_per_m * (s.v.col(b) - s.v.col(a));
    const bool free_a = w[a] != 0, free_b = w[b] != 0;
    if (free_a) {
      add_block(values, &c.diagonal_slot[3 * a], block);
      rhs.col(a) += impulse;
    }
    if (free_b) {
      add_block(values, &c.diagonal_slot[3 * b], block);
      rhs.col(b) -= impulse;
    }
    if (free_a && free_b) {
      add_block(values, &c.ab_slot[3 * j], -block);
      add_block(values, &c.ba_slot[3 * j], -block);
    }
  }
  for_each_poke(model, t_start, [&](int i, double factor, const Eigen::Vector3d& force_N) {
    if (w[i] != 0) rhs.col(i) += h * factor * force_N;
  });
  // Grabs: zero-length springs f = k (target - x) to the handle at the substep's end, so
  // df/dx = -k I on the diagonal.
  for_each_grab(model, t_end, [&](int i, const Eigen::Vector3d& target_m, double compliance_m_per_N) {
    if (w[i] == 0) return;
    const double k = 1.0 / compliance_m_per_N;
    add_identity(values, &c.diagonal_slot[3 * i], h2 * k);
    rhs.col(i) += h * k * (target_m - s.x.col(i)) - h2 * k * s.v.col(i);
  });
}

/// The volume term E = (k_V / 2) (V - V0(t))^2, k_V = 1 / compliance (unit: N/m^5), with the
/// (possibly driven) rest volume at the substep's end, t + h, like the rest lengths: adds
/// h f_V + h^2 df_V/dx v0 to the right-hand side and returns in c.u the factor of its
/// stiffness, h^2 k_V g g^T = u u^T with g = grad V (pinned entries zeroed). The Hessian's
/// other term, k_V (V - V0) d^2V/dx^2, is sparse but indefinite and vanishes at the rest
/// volume; it is dropped, as the geometric term of a compressed spring is clamped.
void add_volume(const Model& model, State& s, ImplicitCache& c, double h, double t_end) {
  const VolumeConstraint& vol = model.volume;
  Eigen::Matrix3Xd& g = s.volume_gradient;
  const double volume = volume_and_gradient(s.x, vol.triangles, g);
  const int n = model.particle_count();
  for (int i = 0; i < n; ++i) {
    if (model.inverse_mass[i] == 0) g.col(i).setZero();
  }
  const double k_v = 1.0 / vol.compliance_m5_per_N;
  const double pressure = -k_v * (volume - driven_rest_volume(model, t_end));  // unit: N/m^2
  double g_dot_v = 0;                                          // dV/dt. unit: m^3/s
  for (int i = 0; i < n; ++i) g_dot_v += g.col(i).dot(s.v.col(i));
  Eigen::Map<Eigen::Matrix3Xd> rhs(c.rhs.data(), 3, n);
  rhs += (h * pressure - h * h * k_v * g_dot_v) * g;
  Eigen::Map<Eigen::Matrix3Xd>(c.u.data(), 3, n) = (h * std::sqrt(k_v)) * g;
}

/// One CG solve of the sparse part from a zero start; counts iterations and failures.
void solve(ImplicitCache& c, const Eigen::VectorXd& b, Eigen::VectorXd& out) {
  out = c.cg.solve(b);
  ++c.solves;
  c.cg_iterations += c.cg.iterations();
  if (c.cg.info() != Eigen::Success) ++c.unconverged_solves;
}

}  // namespace

void implicit_step(const Model& model, State& s, double dt_s) {
  ImplicitCache& c = cache_for(model, s);
  c.cg.setTolerance(kImplicitCgTolerance);
  c.cg.setMaxIterations(kImplicitCgMaxIterations);
  const int substeps = model.substeps;
  const double h = dt_s / substeps;
  const double drag = std::exp(-model.drag_per_s * h);
  const Eigen::Index count = s.x.cols();
  for (int sub = 0; sub < substeps; ++sub) {
    const double t_end = s.time_s + h;
    // Backward Euler evaluates the rest lengths where it evaluates the forces: at t + h.
    update_contractions(model, s, t_end);
    assemble(model, s, c, h, s.time_s, t_end);
    if (model.volume.enabled) add_volume(model, s, c, h, t_end);
    c.cg.compute(c.matrix);  // Only reads the diagonal for the preconditioner.
    solve(c, c.rhs, c.dv);
    c.last_cg_iterations = static_cast<int>(c.cg.iterations());
    if (model.volume.enabled) {
      solve(c, c.u, c.z);
      sherman_morrison_update(c.dv, c.z, c.u);
    }
    const Eigen::Map<const Eigen::Matrix3Xd> dv(c.dv.data(), 3, count);
    for (Eigen::Index i = 0; i < count; ++i) {
      if (model.inverse_mass[i] == 0) continue;
      s.v.col(i) = drag * (s.v.col(i) + dv.col(i));
    }
    drift(model, s, h, t_end);
    settle_on_floor(model, s, h);
    s.time_s = t_end;
  }
}

}  // namespace systole::sim
