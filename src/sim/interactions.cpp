#include "sim/interactions.h"

#include <algorithm>

#include "common/spline.h"
#include "sim/drive.h"

namespace systole::sim {

Eigen::Vector3d path_position(const std::vector<PathKey>& p, double t) {
  return keyed_curve(p, t, [](const PathKey& k) -> const Eigen::Vector3d& { return k.position_m; });
}

double poke_factor(const Poke& poke, double t, double ramp_s) {
  if (poke.drive.waveform != Waveform::kNone) return activation(poke.drive, t, ramp_s);
  return t >= poke.start_s && t < poke.end_s ? 1.0 : 0.0;
}

void move_kinematic_regions(const Model& model, double t, Eigen::Matrix3Xd& x) {
  for (const KinematicRegion& k : model.kinematic) {
    const Eigen::Vector3d offset = path_position(k.motion, t);
    for (int i : k.particles) x.col(i) = model.rest_positions.col(i) + offset;
  }
}

bool grab_active(const Grab& grab, double t) { return t >= grab.path.front().time_s && t <= grab.path.back().time_s; }

void resolve_floor_contact(const Model& model, Eigen::Matrix3Xd& x) {
  if (!model.floor.enabled) return;
  const Eigen::Vector3d& n = model.floor.normal;
  const Eigen::Vector3d& p = model.floor.point_m;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const double depth = (x.col(i) - p).dot(n);
    if (depth < 0) x.col(i) -= depth * n;
  }
}

}  // namespace systole::sim
