#include "mesh/normals.h"

#include <cassert>
#include <cmath>

namespace systole::mesh {

void vertex_normals(const double* xyz, int vertex_count, const std::vector<Eigen::Vector3i>& triangles,
                    float* normals_xyz) {
  // Gather into the output itself (no scratch buffer, so no allocation): face vectors are
  // computed in double and summed in float, in triangle order, one thread: the same bits
  // every run. Float is plenty for a direction made of a handful of terms.
  for (int i = 0; i < 3 * vertex_count; ++i) normals_xyz[i] = 0.0f;
  for (const Eigen::Vector3i& t : triangles) {
    assert((t.array() >= 0).all() && (t.array() < vertex_count).all());
    const double* a = xyz + 3 * t[0];
    const double* b = xyz + 3 * t[1];
    const double* c = xyz + 3 * t[2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    // |u x v| = twice the area: the cross product is already area-weighted.
    const float n[3] = {static_cast<float>(u[1] * v[2] - u[2] * v[1]), static_cast<float>(u[2] * v[0] - u[0] * v[2]),
                        static_cast<float>(u[0] * v[1] - u[1] * v[0])};
    for (int k = 0; k < 3; ++k) {
      float* out = normals_xyz + 3 * t[k];
      out[0] += n[0];
      out[1] += n[1];
      out[2] += n[2];
    }
  }
  for (int i = 0; i < vertex_count; ++i) {
    float* n = normals_xyz + 3 * i;
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0 && std::isfinite(length)) {
      n[0] /= length, n[1] /= length, n[2] /= length;
    } else {
      n[0] = 0.0f, n[1] = 0.0f, n[2] = 1.0f;
    }
  }
}

}  // namespace systole::mesh
