#include "sim/forces.h"

#include <Eigen/Geometry>
#include <cmath>

#include "sim/constraints/volume.h"
#include "sim/solvers/substep.h"

namespace systole::sim {

void internal_and_scripted_forces(const Model& model, const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v,
                                  double t, State& state, Eigen::Matrix3Xd& f) {
  f.setZero();
  // Colour by colour, a colour's springs in parallel: no two touch one particle, so each
  // particle's sum is accumulated in the same order whatever the thread count.
  const Springs& sp = model.springs;
  for (int color = 0; color < sp.colors(); ++color) {
    const int begin = sp.color_begin[color], end = sp.color_begin[color + 1];
#pragma omp parallel for num_threads(model.threads) schedule(static) if (model.threads > 1 && end - begin > 512)
    for (int j = begin; j < end; ++j) {
      const int a = sp.a[j], b = sp.b[j];
      const Eigen::Vector3d d = x.col(b) - x.col(a);
      const double len = d.norm();
      if (len < 1e-12) continue;
      const double k = 1.0 / sp.compliance_m_per_N[j];
      const double c = k * sp.damping_s[j];
      // Hooke spring plus an isotropic damper on the whole relative velocity (Rayleigh
      // damping C = damping_s K of the edge graph): constant in time and position, so every
      // solver integrates exactly the same damping and a factorized solver keeps it in its
      // matrix (docs/accuracy.md: why the damper is not along the spring).
      const Eigen::Vector3d force_a = k * (len - driven_rest_length(sp, j, state.region_contraction)) / len * d +
                                      c * (v.col(b) - v.col(a));
      f.col(a) += force_a;
      f.col(b) -= force_a;
    }
  }
  if (model.volume.enabled) {
    // Pressure from the volume energy E = (K / 2V0) (V - V0)^2: f = -(V - V0) / compliance * dV/dx.
    const double volume = volume_and_gradient(x, model.volume.triangles, state.volume_gradient);
    const double pressure = -(volume - driven_rest_volume(model, t)) / model.volume.compliance_m5_per_N;
    f += pressure * state.volume_gradient;
  }
  for_each_poke(model, t, [&](int i, double factor, const Eigen::Vector3d& force_N) { f.col(i) += factor * force_N; });
  for_each_grab(model, t, [&](int i, const Eigen::Vector3d& target_m, double compliance_m_per_N) {
    const double k = 1.0 / compliance_m_per_N;
    f.col(i) += k * (target_m - x.col(i));
  });
}

}  // namespace systole::sim
