#pragma once
// Small meshes and files for the mesh/ tests.

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <string>

#include "mesh/mesh.h"

namespace systole::mesh::testing {

/// The scratch folder for files a test writes (created on first use).
inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = SYSTOLE_TEST_SCRATCH;
  std::filesystem::create_directories(dir);
  return dir / name;
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

/// A unit cube [0,1]^3, 8 shared vertices, 12 outward triangles.
inline TriangleMesh cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

/// A regular tetrahedron, outward.
inline TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

/// A sphere of `radius` around `center`: an icosahedron subdivided `levels` times.
inline TriangleMesh sphere(int levels, double radius, const Eigen::Vector3d& center) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh m;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : m.positions) p.normalize();
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::vector<Eigen::Vector3i> next;
    for (const auto& f : m.triangles) {
      int mid[3];
      for (int k = 0; k < 3; ++k) {
        m.positions.push_back((m.positions[f[k]] + m.positions[f[(k + 1) % 3]]).normalized());
        mid[k] = static_cast<int>(m.positions.size()) - 1;  // Unshared: welded by the test if needed.
      }
      next.emplace_back(f[0], mid[0], mid[2]);
      next.emplace_back(f[1], mid[1], mid[0]);
      next.emplace_back(f[2], mid[2], mid[1]);
      next.emplace_back(mid[0], mid[1], mid[2]);
    }
    m.triangles = next;
  }
  for (auto& p : m.positions) p = center + radius * p;
  return m;
}

/// Smallest interior angle over all triangles. unit: degrees
inline double min_angle_deg(const TriangleMesh& m) {
  double smallest = 180;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d u = (m.positions[t[(k + 1) % 3]] - m.positions[t[k]]).normalized();
      const Eigen::Vector3d v = (m.positions[t[(k + 2) % 3]] - m.positions[t[k]]).normalized();
      smallest = std::min(smallest, std::acos(std::clamp(u.dot(v), -1.0, 1.0)) * 180.0 / M_PI);
    }
  }
  return smallest;
}

}  // namespace systole::mesh::testing
