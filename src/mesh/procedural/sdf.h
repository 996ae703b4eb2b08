#pragma once
// Signed distance fields for procedural organs: a few smooth primitives blended by a
// smooth minimum. Negative inside, positive outside, about a distance near the surface.
// (Primitive formulas after Inigo Quilez, "Distance functions", iquilezles.org.)

#include <Eigen/Core>
#include <string>
#include <vector>

namespace systole::mesh::procedural {

/// An ellipsoid or a round cone (a capsule whose radius tapers from `a` to `b`).
struct Primitive {
  enum class Kind { kEllipsoid, kRoundCone } kind = Kind::kEllipsoid;
  int part = -1;  ///< Anatomical part the surface near this primitive belongs to.
  // kEllipsoid
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< unit: m
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< Columns: the local axes (orthonormal).
  Eigen::Vector3d radii = Eigen::Vector3d::Ones();    ///< unit: m
  // kRoundCone
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();  ///< unit: m
  double radius_a = 0, radius_b = 0;                                         ///< unit: m
  /// Blend radius with everything added before it (0: a hard union or cut). unit: m
  double blend = 0;
  /// Carves this primitive out of everything added before it (a smooth difference):
  /// notches, impressions, concave faces. A carving primitive owns no surface.
  bool carve = false;

  double distance(const Eigen::Vector3d& p) const;  ///< unit: m (approximate for ellipsoids)
};

Primitive ellipsoid(int part, const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, const Eigen::Vector3d& radii,
                    double blend);
Primitive round_cone(int part, const Eigen::Vector3d& a, double radius_a, const Eigen::Vector3d& b, double radius_b,
                     double blend);

/// Orthonormal axes whose first column points along `along`, the second as close to
/// `towards` as it can (for ellipsoids aligned with a direction).
Eigen::Matrix3d axes_along(const Eigen::Vector3d& along, const Eigen::Vector3d& towards);

/// The same primitive, carving instead of adding (see Primitive::carve).
Primitive carved(Primitive p);

/// Polynomial smooth minimum: equals min(x, y) when they differ by more than k.
double smooth_min(double x, double y, double k);

/// The blended field of primitives, added in order.
struct Field {
  std::vector<Primitive> primitives;

  double distance(const Eigen::Vector3d& p) const;  ///< unit: m
  Eigen::Vector3d gradient(const Eigen::Vector3d& p) const;  ///< Central differences. unit: 1
  /// Index of the adding primitive whose own distance is least at p (the one that owns p).
  int nearest_primitive(const Eigen::Vector3d& p) const;
};

}  // namespace systole::mesh::procedural
