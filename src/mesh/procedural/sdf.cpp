#include "mesh/procedural/sdf.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace systole::mesh::procedural {

Primitive ellipsoid(int part, const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, const Eigen::Vector3d& radii,
                    double blend) {
  Primitive e;
  e.kind = Primitive::Kind::kEllipsoid;
  e.part = part;
  e.center = center;
  e.axes = axes;
  e.radii = radii;
  e.blend = blend;
  return e;
}

Primitive round_cone(int part, const Eigen::Vector3d& a, double radius_a, const Eigen::Vector3d& b, double radius_b,
                     double blend) {
  Primitive c;
  c.kind = Primitive::Kind::kRoundCone;
  c.part = part;
  c.a = a;
  c.b = b;
  c.radius_a = radius_a;
  c.radius_b = radius_b;
  c.blend = blend;
  return c;
}

double Primitive::distance(const Eigen::Vector3d& p) const {
  if (kind == Kind::kEllipsoid) {
    // Quilez's first-order bound k0 (k0 - 1) / k1: exact on the surface, smooth, and
    // close to the distance nearby, which is all the mesher needs.
    const Eigen::Vector3d q = axes.transpose() * (p - center);
    const double k0 = q.cwiseQuotient(radii).norm();
    const double k1 = q.cwiseQuotient(radii.cwiseProduct(radii)).norm();
    if (k1 < 1e-300) return -radii.minCoeff();
    return k0 * (k0 - 1.0) / k1;
  }
  // Exact round cone (Quilez, "sdRoundCone" with arbitrary end points).
  const Eigen::Vector3d ba = b - a;
  const double l2 = ba.squaredNorm();
  const double rr = radius_a - radius_b;
  const double a2 = l2 - rr * rr;
  const double il2 = 1.0 / l2;
  const Eigen::Vector3d pa = p - a;
  const double y = pa.dot(ba);
  const double z = y - l2;
  const double x2 = (pa * l2 - ba * y).squaredNorm();
  const double y2 = y * y * l2;
  const double z2 = z * z * l2;
  const double k = (rr > 0 ? 1.0 : rr < 0 ? -1.0 : 0.0) * rr * rr * x2;
  if ((z > 0 ? 1.0 : z < 0 ? -1.0 : 0.0) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - radius_b;
  if ((y > 0 ? 1.0 : y < 0 ? -1.0 : 0.0) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - radius_a;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - radius_a;
}

Eigen::Matrix3d axes_along(const Eigen::Vector3d& along, const Eigen::Vector3d& towards) {
  const Eigen::Vector3d x = along.normalized();
  const Eigen::Vector3d y = (towards - x * x.dot(towards)).normalized();
  Eigen::Matrix3d m;
  m.col(0) = x;
  m.col(1) = y;
  m.col(2) = x.cross(y);
  return m;
}

Primitive carved(Primitive p) {
  p.carve = true;
  return p;
}

double smooth_min(double x, double y, double k) {
  if (k <= 0) return std::min(x, y);
  const double h = std::max(k - std::abs(x - y), 0.0) / k;
  return std::min(x, y) - h * h * k * 0.25;
}

double Field::distance(const Eigen::Vector3d& p) const {
  double d = primitives.empty() ? 1.0 : primitives.front().distance(p);
  for (size_t i = 1; i < primitives.size(); ++i) {
    const Primitive& q = primitives[i];
    // A smooth difference is the smooth union of the complements: max(d, -e) = -min(-d, e).
    d = q.carve ? -smooth_min(-d, q.distance(p), q.blend) : smooth_min(d, q.distance(p), q.blend);
  }
  return d;
}

Eigen::Vector3d Field::gradient(const Eigen::Vector3d& p) const {
  constexpr double h = 1e-6;  // m: far below any feature, far above rounding.
  Eigen::Vector3d g;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = h;
    g[k] = (distance(p + e) - distance(p - e)) / (2 * h);
  }
  return g;
}

int Field::nearest_primitive(const Eigen::Vector3d& p) const {
  int best = -1;
  double best_distance = 0;
  for (size_t i = 0; i < primitives.size(); ++i) {
    if (primitives[i].carve) continue;
    const double d = primitives[i].distance(p);
    if (best < 0 || d < best_distance) best = static_cast<int>(i), best_distance = d;
  }
  return best;
}

}  // namespace systole::mesh::procedural
