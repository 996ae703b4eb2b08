#pragma once
// A closed, outward-facing box as bare corners and triangles (no mesh types), for tests of
// volumes, gradients and pressure loads whose exact answers are known: volume = product of
// the sides, each face's area vector = its area times its outward normal.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace systole::test {

struct Box {
  Eigen::Matrix3Xd corners;                 ///< 8 corners, corner i at bit (x, y, z) = (i&1, i&2, i&4). unit: m
  std::vector<Eigen::Vector3i> triangles;   ///< 12, outward; face f is triangles 2f and 2f+1.
};

/// The faces' order in Box::triangles: -z, +z, -y, +y, -x, +x.
enum BoxFace { kBottom = 0, kTop = 1, kFront = 2, kBack = 3, kLeft = 4, kRight = 5 };

/// An axis-aligned box of sides (a, b, c) with its lowest corner at `origin`. unit: m
inline Box box(double a, double b, double c, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero()) {
  Box out;
  out.corners.resize(3, 8);
  for (int i = 0; i < 8; ++i) out.corners.col(i) = origin + Eigen::Vector3d(i & 1 ? a : 0, i & 2 ? b : 0, i & 4 ? c : 0);
  // Each face as a quad (p, q, r, s) turning counter-clockwise seen from outside.
  const std::array<std::array<int, 4>, 6> quads{{
      {0, 2, 3, 1},  // -z
      {4, 5, 7, 6},  // +z
      {0, 1, 5, 4},  // -y
      {2, 6, 7, 3},  // +y
      {0, 4, 6, 2},  // -x
      {1, 3, 7, 5},  // +x
  }};
  for (const auto& q : quads) {
    out.triangles.emplace_back(q[0], q[1], q[2]);
    out.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return out;
}

}  // namespace systole::test
