#include "mesh/simplify.h"

#include <meshoptimizer.h>

namespace systole::mesh {

SimplifiedTriangles simplify(const TriangleMesh& surface, double max_error_m) {
  std::vector<float> positions;
  positions.reserve(3 * surface.positions.size());
  for (const auto& p : surface.positions) {
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(p[k]));
  }
  std::vector<unsigned> indices;
  indices.reserve(3 * surface.triangles.size());
  for (const auto& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<unsigned>(t[k]));
  }
  const std::size_t vertices = surface.positions.size();
  // meshoptimizer measures error relative to the mesh's extent.
  const float scale = meshopt_simplifyScale(positions.data(), vertices, 3 * sizeof(float));
  std::vector<unsigned> kept(indices.size());
  float error = 0;
  const std::size_t count =
      scale > 0 ? meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(), vertices,
                                   3 * sizeof(float), 0, static_cast<float>(max_error_m / scale),
                                   meshopt_SimplifyLockBorder, &error)
                : 0;
  if (count == 0) {  // Nothing to measure, or nothing left: draw every triangle.
    kept = indices;
    error = 0;
  } else {
    kept.resize(count);
  }
  meshopt_optimizeVertexCache(kept.data(), kept.data(), kept.size(), vertices);
  SimplifiedTriangles out;
  out.error_m = static_cast<double>(error) * scale;
  out.triangles.reserve(kept.size() / 3);
  for (std::size_t i = 0; i + 2 < kept.size(); i += 3) {
    out.triangles.emplace_back(static_cast<int>(kept[i]), static_cast<int>(kept[i + 1]), static_cast<int>(kept[i + 2]));
  }
  return out;
}

}  // namespace systole::mesh
