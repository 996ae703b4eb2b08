#pragma once
// Shared by the training tests: a small ball mesh written as OBJ, key frames of it, and
// scenes around it, all in the test's scratch folder.

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace systole::train::testing {

inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// An icosphere of radius 3 cm: 12 vertices subdivided `levels` times (42, 162, ... vertices).
struct Ball {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
};

inline Ball icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Ball b;
  for (auto v : {Eigen::Vector3d(-1, t, 0), Eigen::Vector3d(1, t, 0), Eigen::Vector3d(-1, -t, 0), Eigen::Vector3d(1, -t, 0),
                 Eigen::Vector3d(0, -1, t), Eigen::Vector3d(0, 1, t), Eigen::Vector3d(0, -1, -t), Eigen::Vector3d(0, 1, -t),
                 Eigen::Vector3d(t, 0, -1), Eigen::Vector3d(t, 0, 1), Eigen::Vector3d(-t, 0, -1), Eigen::Vector3d(-t, 0, 1)})
    b.vertices.push_back(v.normalized());
  b.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int i, int j) {
      const auto key = std::make_pair(std::min(i, j), std::max(i, j));
      if (auto it = middle.find(key); it != middle.end()) return it->second;
      b.vertices.push_back((b.vertices[i] + b.vertices[j]).normalized());
      return middle[key] = static_cast<int>(b.vertices.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& f : b.triangles) {
      const int a = mid(f[0], f[1]), c = mid(f[1], f[2]), d = mid(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, d}, {f[1], c, a}, {f[2], d, c}, {a, c, d}});
    }
    b.triangles = next;
  }
  for (auto& v : b.vertices) v *= 0.03;
  return b;
}

inline void write_obj(const std::filesystem::path& path, const std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& triangles) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& v : vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& f : triangles) out << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
}

inline void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

/// The ball scene: two regions (upper and lower half), each with the drive text given.
inline std::string ball_scene(const std::string& top_drive, const std::string& bottom_drive, const std::string& target,
                              const std::string& extra_region_keys = "") {
  return "seed: 7\n"
         "organs:\n"
         "  - name: ball\n"
         "    mesh: {file: ball.obj}\n"
         "    body: {mass: 100 g, stiffness: 200 N/m, damping: 20 ms, volume_stiffness: 1 kPa, drag: 4 1/s}\n"
         "    regions:\n"
         "      - {name: top, select: {half_space: {normal: [0, 1, 0]}}, drive: " + top_drive + extra_region_keys + "}\n"
         "      - {name: bottom, select: {half_space: {normal: [0, -1, 0], point: [0, -0.0001, 0]}}, drive: " + bottom_drive + "}\n" +
         target +
         "solver: {dt: 1/120 s, substeps: 2}\n"
         "output: {width: 64, height: 48, fps: 30, duration: 1 s}\n";
}

}  // namespace systole::train::testing
