#pragma once
// Small closed surfaces for simulation tests, so tests/sim needs no mesh generator.

#include <Eigen/Core>
#include <vector>

#include "mesh/icosphere.h"
#include "mesh/inspect.h"
#include "mesh/organ.h"

namespace systole::test {

/// A geodesic sphere of `radius_m` (mesh/icosphere.h).
inline mesh::TriangleMesh icosphere(double radius_m, int levels) { return mesh::icosphere(radius_m, levels); }

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
