#pragma once
// Triangle surfaces of organs: what mesh/ produces (from a file or a generator) and sim/
// and render/ consume.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace systole::mesh {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> positions;  ///< unit: m
  std::vector<Eigen::Vector3i> triangles;  ///< Counter-clockwise seen from outside.
};

/// A surface with named parts: a generator's anatomical parts, or a file's sub-meshes.
struct OrganMesh {
  TriangleMesh surface;
  std::vector<std::string> part_names;
  std::vector<int> vertex_part;  ///< Per vertex: index into part_names, or -1 for none.
  /// Triangles the import left out: a corner repeated, in the file or once vertices closer
  /// than the weld tolerance became one (validate's mesh report says how many).
  int dropped_triangles = 0;

  int part_index(const std::string& name) const;  ///< -1 if absent.
};

}  // namespace systole::mesh
