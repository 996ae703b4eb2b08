#pragma once
// Small closed surfaces for simulation tests, so tests/sim needs no mesh generator.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <map>
#include <utility>
#include <vector>

#include "mesh/inspect.h"
#include "mesh/organ.h"

namespace systole::test {

/// Unit-radius icosphere scaled to `radius_m`, subdivided `levels` times, outward CCW.
inline mesh::TriangleMesh icosphere(double radius_m, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& v : p) v.normalize();
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return mid[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  mesh::TriangleMesh m;
  for (auto& v : p) m.positions.push_back(v * radius_m);
  m.triangles = f;
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
