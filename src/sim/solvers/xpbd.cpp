#include "sim/solvers/xpbd.h"

#include <Eigen/Geometry>
#include <cmath>

#include "sim/constraints/attachment.h"
#include "sim/constraints/distance.h"
#include "sim/constraints/volume.h"
#include "sim/forces.h"
#include "sim/solvers/substep.h"

namespace systole::sim {

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
      s.spring_lambda[j] += solve_distance(x + 3 * a, x + 3 * b, d_a, d_b, w[a], w[b],
                                           driven_rest_length(sp, j, s.region_contraction), alpha_tilde, 0.0);
    }
  }
}

/// The springs' isotropic dampers (sim/forces.h) on the new velocities, each pair solved
/// implicitly: (v_b - v_a)' = (v_b - v_a) / (1 + h c (w_a + w_b)), the velocity pass of
/// Müller et al., "Position Based Dynamics" (2007) §3.5 made per spring. One Gauss-Seidel
/// pass, colour by colour like the positions; it converges to the same damping as the
/// other solvers only as h c w << 1 (docs/accuracy.md: why XPBD needs tiny substeps on
/// stiff, damped bodies).
void damp_springs(const Model& model, State& s, double h) {
  const Springs& sp = model.springs;
  const Eigen::VectorXd& w = model.inverse_mass;
  for (int color = 0; color < sp.colors(); ++color) {
    const int begin = sp.color_begin[color], end = sp.color_begin[color + 1];
#pragma omp parallel for num_threads(model.threads) schedule(static) if (model.threads > 1 && end - begin > 512)
    for (int j = begin; j < end; ++j) {
      const int a = sp.a[j], b = sp.b[j];
      const double c_h = h * sp.damping_s[j] / sp.compliance_m_per_N[j];
      const Eigen::Vector3d relative = s.v.col(b) - s.v.col(a);
      const Eigen::Vector3d impulse = c_h / (1.0 + c_h * (w[a] + w[b])) * relative;
      s.v.col(a) += w[a] * impulse;
      s.v.col(b) -= w[b] * impulse;
    }
  }
}

/// The global volume constraint (sim/constraints/volume.h) at the substep's end.
void solve_volume_constraint(const Model& model, State& s, double t, double h) {
  const VolumeConstraint& vol = model.volume;
  if (!vol.enabled) return;
  const double volume = volume_and_gradient(s.x, vol.triangles, s.volume_gradient);
  const double c = volume - driven_rest_volume(model, t);
  const double alpha_tilde = vol.compliance_m5_per_N / (h * h);
  s.volume_lambda += solve_volume(s.x, model.inverse_mass, s.volume_gradient, c, alpha_tilde, s.volume_lambda);
}

/// Grabs as zero-length attachments to moving targets (XPBD eq. 18 with the target's
/// inverse mass 0).
void solve_grabs(const Model& model, State& s, double t, double h) {
  const double no_motion[3] = {0, 0, 0};
  for_each_grab(model, t, [&](int i, const Eigen::Vector3d& target_m, double compliance_m_per_N) {
    const double alpha_tilde = compliance_m_per_N / (h * h);
    Eigen::Vector3d target = target_m;
    solve_distance(target.data(), s.x.col(i).data(), no_motion, no_motion, 0.0, model.inverse_mass[i], 0.0,
                   alpha_tilde, 0.0);
  });
}

/// Attachments to the training target (sim/constraints/attachment.h): per particle and
/// axis one multiplier.
void solve_attachments(const Model& model, const Attachments* coupling, State& s, double t, double h) {
  if (!coupling || !coupling->enabled()) return;
  coupling->target(t, s.attachment_target);
  const double alpha_tilde = coupling->compliance_m_per_N / (h * h);
  if (coupling->points != nullptr && !coupling->points->empty()) {
    // Jacobi passes converge slower than Gauss-Seidel's: on the anatomical heart tied to its
    // own motion the walls' floor is 11-19 % of their motion after one pass per substep, 3-7 %
    // after four, 0.2-0.6 % after sixteen, at a small share of the coupled run's cost.
    constexpr int kPasses = 4;
    for (int pass = 0; pass < kPasses; ++pass) {
      solve_embedded_attachments(s.x, *coupling->points, s.attachment_target, model.inverse_mass, alpha_tilde,
                                 s.attachment_lambda, s.attachment_pull, s.attachment_hold);
    }
    return;
  }
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    s.attachment_lambda.col(i) +=
        solve_attachment(s.x.col(i), s.attachment_target.col(i), model.inverse_mass[i], alpha_tilde);
  }
}

}  // namespace

void xpbd_step(const Model& model, State& s, double dt_s, const Attachments* coupling) {
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
    for_each_poke(model, s.time_s, [&](int i, double factor, const Eigen::Vector3d& force_N) {
      s.v.col(i) += h * factor * model.inverse_mass[i] * force_N;
    });
    drift(model, s, h, t_end);
    update_contractions(model, s, t_end);
    s.spring_lambda.setZero();
    s.volume_lambda = 0;
    if (coupling) s.attachment_lambda.setZero();
    solve_springs(model, s, h);
    solve_volume_constraint(model, s, t_end, h);
    solve_grabs(model, s, t_end, h);
    solve_attachments(model, coupling, s, t_end, h);
    resolve_floor_contact(model, s.x);
    s.v = (s.x - s.x_prev) / h;
    damp_springs(model, s, h);
    s.time_s = t_end;
  }
}

}  // namespace systole::sim
