#pragma once
// Fewer triangles to draw for a big mesh. A software rasterizer pays for every triangle
// whatever its size (llvmpipe: 65 ms a frame for a 163k-triangle atlas heart, at 320x240 as
// at 1280x720), so a mesh whose triangles are smaller than the pixels that show them is
// drawn simplified: meshoptimizer's edge collapses, bounded by a distance from the full
// surface. The triangles keep the surface's own vertices, so the drawn mesh still follows
// the body vertex for vertex; open borders are kept where they are.

#include <vector>

#include "mesh/mesh.h"

namespace systole::mesh {

struct SimplifiedTriangles {
  std::vector<Eigen::Vector3i> triangles;  ///< Over the surface's vertices, in vertex-cache order.
  /// meshoptimizer's measure of the simplification: how far the removed vertices lie from
  /// the simplified surface. Between vertices the surface strays further: up to twice
  /// that on a sphere (tests/mesh/simplify_test.cpp). unit: m
  double error_m = 0;
};

/// The fewest triangles of `surface` (at its positions) whose error_m is at most
/// `max_error_m`, ordered for the rasterizer's vertex cache.
SimplifiedTriangles simplify(const TriangleMesh& surface, double max_error_m);

}  // namespace systole::mesh
