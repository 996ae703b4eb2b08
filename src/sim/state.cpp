#include "sim/state.h"

namespace systole::sim {

State initial_state(const Model& model) {
  State s;
  const Eigen::Index n = model.particle_count();
  s.x = model.rest_positions;
  s.v = Eigen::Matrix3Xd::Zero(3, n);
  s.spring_lambda = Eigen::VectorXd::Zero(model.springs.size());
  s.x_prev = s.x;
  s.region_contraction = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.regions.size()) + model.excited.size());
  s.volume_gradient = Eigen::Matrix3Xd::Zero(3, model.volume.enabled ? n : 0);
  s.force = Eigen::Matrix3Xd::Zero(3, n);
  s.attachment_lambda = Eigen::Matrix3Xd::Zero(3, n);  // Written only while a coupling is passed to step.
  s.attachment_target = s.attachment_lambda;
  s.attachment_pull = s.attachment_lambda;
  s.attachment_hold = Eigen::VectorXd::Zero(n);
  for (const Chamber& chamber : model.circulation.chambers) {
    ChamberState c;
    c.volume_m3 = chamber.rest_m3;
    c.pressure_Pa = model.circulation.filling_Pa;
    s.chambers.push_back(c);
  }
  return s;
}

}  // namespace systole::sim
