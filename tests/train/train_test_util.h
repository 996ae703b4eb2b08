#pragma once
// Shared by the training tests: a small ball mesh written as OBJ, key frames of it, and
// scenes around it, all in the test's scratch folder; the figures `tune` prints and reports.

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "mesh/icosphere.h"

namespace systole::train::testing {

inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The training tests' ball: a 3 cm icosphere (mesh/icosphere.h), `levels` subdivisions.
inline mesh::TriangleMesh icosphere(int levels) { return mesh::icosphere(0.03, levels); }

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
         "solver: {method: xpbd, dt: 1/120 s, substeps: 2}\n"
         "output: {width: 64, height: 48, fps: 30, duration: 1 s}\n";
}

/// An error `tune` prints ("as written", "tuned"): drives against the target; -1 when it
/// printed none. unit: %
inline double printed_pct(const std::string& output, const std::string& which) {
  std::smatch m;
  const std::regex line(which + R"(: RMS ([0-9.e+-]+) % of the target's motion)");
  return std::regex_search(output, m, line) ? std::stod(m[1]) : -1;
}

/// The tuned value of `parameter` ("upper_pole.amplitude") in the report's parameter table;
/// -1 when it has none. Same unit as the scene's.
inline double tuned_value(const std::string& report, const std::string& parameter) {
  std::smatch m;
  const std::regex row("\\| " + parameter + " \\| [0-9.e+-]+ \\| ([0-9.e+-]+) \\|");
  return std::regex_search(report, m, row) ? std::stod(m[1]) : -1;
}

}  // namespace systole::train::testing
