#pragma once
// Triangle surfaces of organs: what mesh/ produces (from a file or a generator) and sim/
// and render/ consume.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "mesh/anatomy.h"

namespace systole::mesh {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> positions;  ///< unit: m
  std::vector<Eigen::Vector3i> triangles;  ///< Counter-clockwise seen from outside.
};

/// A surface with named parts: a generator's anatomical parts, or a file's parts as its
/// author named them (meshes, nodes, group nodes, materials).
struct OrganMesh {
  TriangleMesh surface;
  std::vector<std::string> part_names;
  std::vector<int> vertex_part;  ///< Per vertex: its first part (index into part_names), or -1 for none.
  /// Every other part a vertex belongs to, as sorted, unique (vertex, part) pairs: a vertex
  /// welded from several parts' surfaces (a valve ring on a chamber wall) belongs to each, and
  /// a group node's part holds every vertex of the meshes under it.
  std::vector<std::pair<int, int>> also_in;
  /// Triangles the import left out: a corner repeated, in the file or once vertices closer
  /// than the weld tolerance became one (validate's mesh report says how many).
  int dropped_triangles = 0;
  /// The generator's volumetric body, cavities, valves and landmarks (the anatomical heart);
  /// empty for a surface from a file.
  Anatomy anatomy;

  int part_index(const std::string& name) const;  ///< -1 if absent.
  /// The parts a selector's `name` means: the part of exactly that name, else every part
  /// whose name ends in "/" + name, so "left_atrium" finds an exported organ's
  /// "heart/left_atrium". One is a match, none unknown, several ambiguous (the caller says).
  std::vector<int> parts_named(const std::string& name) const;
  /// Per vertex: 1 if it belongs to `part` (first or otherwise), else 0.
  std::vector<char> part_mask(int part) const;
  /// Sorts also_in, drops duplicates and pairs that repeat a vertex's first part.
  void normalize_membership();
  /// The triangles whose three corners belong to `part`, over the same vertices.
  TriangleMesh part_surface(int part) const;
  /// Every part's surface at once, each over its own vertices only (in the surface's order):
  /// one pass over the triangles, so the cost grows with the mesh, not with parts x mesh
  /// (validate's part list of an atlas of 20,000 parts).
  std::vector<TriangleMesh> part_surfaces() const;
};

}  // namespace systole::mesh
