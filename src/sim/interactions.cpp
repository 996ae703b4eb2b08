#include "sim/interactions.h"

#include <algorithm>

#include "sim/drive.h"

namespace systole::sim {

Eigen::Vector3d path_position(const std::vector<scene::PathKey>& p, double t) {
  if (p.size() == 1 || t <= p.front().time_s) return p.front().position_m;
  if (t >= p.back().time_s) return p.back().position_m;
  const auto next = std::upper_bound(p.begin(), p.end(), t, [](double v, const scene::PathKey& k) { return v < k.time_s; });
  const std::size_t i = static_cast<std::size_t>(next - p.begin()) - 1;
  const double u = (t - p[i].time_s) / (p[i + 1].time_s - p[i].time_s);
  // Catmull-Rom with end keys repeated (Catmull & Rom 1974).
  const Eigen::Vector3d& p0 = p[i == 0 ? 0 : i - 1].position_m;
  const Eigen::Vector3d& p1 = p[i].position_m;
  const Eigen::Vector3d& p2 = p[i + 1].position_m;
  const Eigen::Vector3d& p3 = p[std::min(i + 2, p.size() - 1)].position_m;
  return 0.5 * ((2 * p1) + (-p0 + p2) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u + (-p0 + 3 * p1 - 3 * p2 + p3) * u * u * u);
}

double poke_factor(const Poke& poke, double t, double ramp_s) {
  if (poke.drive.waveform != scene::Waveform::kNone) return activation(poke.drive, t, ramp_s);
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
