#pragma once
// Small surfaces for tests: closed ones for simulation (so tests/sim needs no mesh
// generator), and flat open sheets.

#include <Eigen/Core>
#include <vector>

#include "mesh/icosphere.h"
#include "mesh/inspect.h"
#include "mesh/organ.h"

namespace systole::test {

/// A geodesic sphere of `radius_m` (mesh/icosphere.h).
inline mesh::TriangleMesh icosphere(double radius_m, int levels) { return mesh::icosphere(radius_m, levels); }

/// An n x n grid of squares of side size_m / n in a plane of constant z, two triangles a
/// square, facing +z, its lowest corner at `corner_m`: an open surface.
inline mesh::TriangleMesh sheet(int n, double size_m, const Eigen::Vector3d& corner_m = Eigen::Vector3d::Zero()) {
  mesh::TriangleMesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) m.positions.push_back(corner_m + size_m * Eigen::Vector3d(double(i) / n, double(j) / n, 0));
  }
  const auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      m.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return m;
}

/// Geometry for sim::build_model, inspected as the real pipeline does (so a broken
/// surface gets no volume constraint), with per-vertex regions.
inline mesh::OrganGeometry geometry_of(const mesh::TriangleMesh& surface, std::vector<int> vertex_region) {
  mesh::OrganGeometry g;
  g.mesh.surface = surface;
  g.vertex_region = std::move(vertex_region);
  g.report = mesh::inspect(surface);
  return g;
}

}  // namespace systole::test
