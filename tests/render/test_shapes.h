#pragma once
// Small shapes for render tests, built here so the tests do not depend on mesh/.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace systole::render::testing {

// Set before main, so before the first context of the process: no shader disk-cache thread
// writing to ~/.cache, and llvmpipe's thread count fixed for every render test.
inline const bool kEnvironment = [] {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  setenv("LP_NUM_THREADS", "2", 0);
  return true;
}();

struct Shape {
  std::vector<float> positions;  ///< xyz per vertex. unit: m
  std::vector<float> normals;    ///< xyz per vertex, unit length.
  std::vector<Eigen::Vector3i> triangles;  ///< Counter-clockwise seen from outside.

  int vertex_count() const { return static_cast<int>(positions.size() / 3); }
  Eigen::Vector3f position(int v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
  void translate(const Eigen::Vector3f& offset) {
    for (std::size_t v = 0; v < positions.size(); v += 3) {
      for (int k = 0; k < 3; ++k) positions[v + k] += offset[k];
    }
  }
};

/// A UV sphere with `stacks` latitude bands and `slices` longitude segments:
/// 2 * slices * (stacks - 1) triangles, poles on the y axis.
inline Shape uv_sphere(const Eigen::Vector3f& center, float radius, int stacks, int slices) {
  Shape s;
  const double pi = std::numbers::pi;
  for (int i = 0; i <= stacks; ++i) {
    const double theta = pi * i / stacks;  // 0 at the north pole (+y).
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2 * pi * j / slices;
      const Eigen::Vector3f n(static_cast<float>(std::sin(theta) * std::cos(phi)),
                              static_cast<float>(std::cos(theta)),
                              static_cast<float>(-std::sin(theta) * std::sin(phi)));
      const Eigen::Vector3f p = center + radius * n;
      s.positions.insert(s.positions.end(), {p.x(), p.y(), p.z()});
      s.normals.insert(s.normals.end(), {n.x(), n.y(), n.z()});
    }
  }
  const auto index = [&](int i, int j) { return i * (slices + 1) + j; };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      if (i != 0) s.triangles.emplace_back(a, b, d);
      if (i != stacks - 1) s.triangles.emplace_back(b, c, d);
    }
  }
  return s;
}

/// One triangle in the z = `z` plane, counter-clockwise seen from +z, normal +z.
inline Shape triangle(float size, float z) {
  Shape s;
  s.positions = {-size, -size, z, size, -size, z, 0.2f * size, size, z};
  s.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  s.triangles = {Eigen::Vector3i(0, 1, 2)};
  return s;
}

}  // namespace systole::render::testing
