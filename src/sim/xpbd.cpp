#include "sim/xpbd.h"

#include <Eigen/Geometry>
#include <cmath>

#include "sim/drive.h"
#include "sim/forces.h"
#include "sim/interactions.h"

namespace systole::sim {

double solve_distance(double* xa, double* xb, const double* da, const double* db, double wa, double wb,
                      double rest, double alpha_tilde, double gamma) {
  const double w = wa + wb;
  if (w == 0) return 0;
  const double dx = xb[0] - xa[0], dy = xb[1] - xa[1], dz = xb[2] - xa[2];
  const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (len < 1e-12) return 0;  // Direction undefined; neighbours will separate them.
  const double nx = dx / len, ny = dy / len, nz = dz / len;
  const double c = len - rest;
  // Relative motion along the constraint this substep: what the damping term resists.
  const double rel = nx * (db[0] - da[0]) + ny * (db[1] - da[1]) + nz * (db[2] - da[2]);
  const double dlambda = (-c - gamma * rel) / ((1.0 + gamma) * w + alpha_tilde);
  xa[0] -= wa * dlambda * nx;
  xa[1] -= wa * dlambda * ny;
  xa[2] -= wa * dlambda * nz;
  xb[0] += wb * dlambda * nx;
  xb[1] += wb * dlambda * ny;
  xb[2] += wb * dlambda * nz;
  return dlambda;
}

namespace {

/// All springs, colour by colour. Springs of one colour share no particle, so a colour's
/// springs run on model.threads threads with the same result as in order: determinism does
/// not depend on the thread count.
void solve_springs(const Model& model, State& s, double h) {
  const Springs& sp = model.springs;
  const double* w = model.inverse_mass.data();
  double* x = s.x.data();
  const double* xp = s.x_prev.data();
  const double inv_h2 = 1.0 / (h * h);
  for (int color = 0; color < sp.colors(); ++color) {
    const int begin = sp.color_begin[color], end = sp.color_begin[color + 1];
#pragma omp parallel for num_threads(model.threads) schedule(static) if (model.threads > 1 && end - begin > 512)
    for (int j = begin; j < end; ++j) {
      const int a = sp.a[j], b = sp.b[j];
      double d_a[3], d_b[3];
      for (int k = 0; k < 3; ++k) {
        d_a[k] = x[3 * a + k] - xp[3 * a + k];
        d_b[k] = x[3 * b + k] - xp[3 * b + k];
      }
      const double alpha_tilde = sp.compliance_m_per_N[j] * inv_h2;
      const double gamma = sp.damping_s[j] / h;
      s.spring_lambda[j] += solve_distance(x + 3 * a, x + 3 * b, d_a, d_b, w[a], w[b],
                                           driven_rest_length(sp, j, s.region_contraction), alpha_tilde, gamma);
    }
  }
}

/// Global volume constraint C = V(x) - V0 (Müller et al., "Position Based Dynamics", 2007,
/// §4.4, in XPBD form): one multiplier for the whole surface.
void solve_volume(const Model& model, State& s, double t, double h) {
  const VolumeConstraint& vol = model.volume;
  if (!vol.enabled) return;
  Eigen::Matrix3Xd& g = s.volume_gradient;
  g.setZero();
  double six_v = 0;
  for (const auto& t : vol.triangles) {
    const auto p0 = s.x.col(t[0]), p1 = s.x.col(t[1]), p2 = s.x.col(t[2]);
    six_v += p0.dot(p1.cross(p2));
    g.col(t[0]) += p1.cross(p2);
    g.col(t[1]) += p2.cross(p0);
    g.col(t[2]) += p0.cross(p1);
  }
  g /= 6.0;
  const double c = six_v / 6.0 - driven_rest_volume(model, t);
  double denom = 0;
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) denom += model.inverse_mass[i] * g.col(i).squaredNorm();
  const double alpha_tilde = vol.compliance_m5_per_N / (h * h);
  if (denom + alpha_tilde <= 0) return;
  const double dlambda = (-c - alpha_tilde * s.volume_lambda) / (denom + alpha_tilde);
  s.volume_lambda += dlambda;
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) s.x.col(i) += model.inverse_mass[i] * dlambda * g.col(i);
}

/// Grabs as zero-length attachments to moving targets (XPBD eq. 18 with the target's
/// inverse mass 0).
void solve_grabs(const Model& model, State& s, double t, double h) {
  const double no_motion[3] = {0, 0, 0};
  for (const Grab& g : model.grabs) {
    if (!grab_active(g, t)) continue;
    const Eigen::Vector3d handle = handle_position(g, t);
    const double alpha_tilde = g.compliance_m_per_N / (h * h);
    for (std::size_t k = 0; k < g.particles.size(); ++k) {
      const int i = g.particles[k];
      Eigen::Vector3d target = handle + g.offsets_m[k];
      solve_distance(target.data(), s.x.col(i).data(), no_motion, no_motion, 0.0, model.inverse_mass[i], 0.0,
                     alpha_tilde, 0.0);
    }
  }
}

/// Attachments to the training target: per particle and axis, C = x - target with
/// compliance alpha (XPBD eq. 18 with the target's inverse mass 0), one multiplier each.
void solve_attachments(const Model& model, State& s, double t, double h) {
  if (!model.attachments.enabled()) return;
  model.attachments.target(t, s.attachment_target);
  const double alpha_tilde = model.attachments.compliance_m_per_N / (h * h);
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const double w = model.inverse_mass[i];
    if (w == 0) continue;
    const Eigen::Vector3d dlambda = -(s.x.col(i) - s.attachment_target.col(i)) / (w + alpha_tilde);
    s.attachment_lambda.col(i) += dlambda;
    s.x.col(i) += w * dlambda;
  }
}

}  // namespace

void xpbd_step(const Model& model, State& s, double dt_s) {
  const int n = model.substeps;
  const double h = dt_s / n;
  const double drag = std::exp(-model.drag_per_s * h);
  const Eigen::Index count = s.x.cols();
  for (int sub = 0; sub < n; ++sub) {
    const double t_end = s.time_s + h;
    for (Eigen::Index i = 0; i < count; ++i) {
      if (model.inverse_mass[i] == 0) continue;
      s.v.col(i) = drag * (s.v.col(i) + h * model.gravity);
    }
    for (const Poke& p : model.pokes) {
      const double factor = poke_factor(p, s.time_s, model.ramp_s);
      if (factor == 0) continue;
      for (int i : p.particles) s.v.col(i) += h * factor * model.inverse_mass[i] * p.force_per_particle_N;
    }
    s.x_prev = s.x;
    s.x += h * s.v;
    move_kinematic_regions(model, t_end, s.x);
    region_contractions(model.regions, model.beat_boundaries, t_end, model.ramp_s, s.region_contraction);
    s.spring_lambda.setZero();
    s.volume_lambda = 0;
    s.attachment_lambda.setZero();
    solve_springs(model, s, h);
    solve_volume(model, s, t_end, h);
    solve_grabs(model, s, t_end, h);
    solve_attachments(model, s, t_end, h);
    resolve_floor_contact(model, s.x);
    s.v = (s.x - s.x_prev) / h;
    s.time_s = t_end;
  }
}

}  // namespace systole::sim
