#include "train/coupling.h"

#include <Eigen/Dense>

#include "sim/forces.h"
#include "world/frame_source.h"

namespace systole::train {

RecordedSignals record_coupled(const Problem& problem, const sim::Model& base, double coupling_N_per_m,
                               const std::vector<int>& fitted) {
  const sim::Model model = sim::with_method(base, sim::Method::kXpbd);  // Attachments are XPBD constraints.
  const TargetMotion& target = problem.target;
  const double rate = problem.rate_hz;
  sim::Attachments coupling;
  coupling.target = [&target, rate](double t_s, Eigen::Matrix3Xd& out) { target.positions(rate * t_s, out); };
  coupling.compliance_m_per_N = 1.0 / coupling_N_per_m;

  RecordedSignals rec;
  rec.contraction.assign(model.regions.size(), {});
  // The coupled body played alone; the recorder listens after every measured step.
  world::BodyPlayback playback(model, problem.dt_s, &coupling);
  const sim::State& state = playback.state();
  const int n = model.particle_count(), columns = static_cast<int>(fitted.size());
  std::vector<int> column_of(model.regions.size(), -1);
  for (int c = 0; c < columns; ++c) column_of[fitted[c]] = c;
  const double h = problem.dt_s / model.substeps;
  const sim::Springs& sp = model.springs;
  Eigen::MatrixXd jacobian(3 * n, columns);
  double force_sum = 0;
  playback.run(problem.settle_steps);
  playback.run(problem.measure_steps, [&](int) {
    // Force of the attachments on each particle in the last substep (pinned ones have none).
    const Eigen::Matrix3Xd force = state.attachment_lambda / (h * h);
    jacobian.setZero();
    for (int j = 0; j < sp.size(); ++j) {
      const int a = sp.a[j], b = sp.b[j];
      const Eigen::Vector3d d = state.x.col(b) - state.x.col(a);
      const double len = d.norm();
      if (len < 1e-12) continue;
      // The spring's force as one XPBD iteration exerts it, lambda / h^2 = -C / (h^2 w + alpha)
      // (XPBD eq. 18; the damper is a separate velocity pass): below the stiffness 1 / alpha
      // when the particles are light.
      const double k = 1.0 / (h * h * (model.inverse_mass[a] + model.inverse_mass[b]) + sp.compliance_m_per_N[j]);
      const Eigen::Vector3d gradient = (k * sp.rest_m[j] / len) * d;  // k L0 n
      for (int end : {sp.region_a[j], sp.region_b[j]}) {
        const int c = end >= 0 ? column_of[end] : -1;
        if (c < 0) continue;
        // Contracting the spring pulls b towards a and a towards b (half per end region).
        if (model.inverse_mass[b] > 0) jacobian.block<3, 1>(3 * b, c) -= 0.5 * gradient;
        if (model.inverse_mass[a] > 0) jacobian.block<3, 1>(3 * a, c) += 0.5 * gradient;
      }
    }
    const Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(force.data(), 3 * n);
    // Normal equations of a few columns; a tiny ridge keeps a region the forces cannot see at 0.
    Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
    normal.diagonal().array() += 1e-9 * (normal.diagonal().maxCoeff() + 1e-30);
    const Eigen::VectorXd dc = normal.ldlt().solve(jacobian.transpose() * f);
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
      const double now = state.region_contraction[static_cast<Eigen::Index>(r)];
      rec.contraction[r].push_back(now + (column_of[r] >= 0 ? dc[column_of[r]] : 0.0));
    }
    rec.times_s.push_back(state.time_s);
    force_sum += force.colwise().norm().sum() / n;
  });
  rec.mean_coupling_force_N = force_sum / problem.measure_steps;
  return rec;
}

}  // namespace systole::train
