#pragma once
// Mesh validation that reports instead of crashing: what is wrong, where, and what
// Systole does about it.

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace systole::mesh {

struct MeshReport {
  int vertices = 0;
  int triangles = 0;
  int invalid_triangles = 0;     ///< An index out of range, or a non-finite position: ignored below.
  int degenerate_triangles = 0;  ///< Zero area or repeated vertex index.
  int boundary_edges = 0;        ///< Edges with one triangle: the surface is open.
  int nonmanifold_edges = 0;     ///< Edges with three or more triangles.
  int inconsistent_edges = 0;    ///< Edges whose two triangles disagree on orientation.
  int components = 0;            ///< Connected pieces (of triangles; unused vertices not counted).
  int unused_vertices = 0;       ///< Vertices no triangle uses.
  double volume_m3 = 0;          ///< Signed enclosed volume (meaningful when closed).
  /// Per vertex: its connected piece is closed (every edge on exactly two triangles that run
  /// it in opposite directions) and faces outwards (positive volume), so its back faces are
  /// always hidden by its front ones.
  std::vector<char> in_closed_piece;
  std::vector<std::string> notes;  ///< One line per finding, with an example location.

  bool closed() const { return triangles > 0 && boundary_edges == 0 && nonmanifold_edges == 0; }
  bool clean() const {
    return closed() && invalid_triangles == 0 && degenerate_triangles == 0 && inconsistent_edges == 0;
  }
  /// A closed, consistently oriented surface: its volume means something.
  bool encloses_volume() const { return closed() && invalid_triangles == 0 && inconsistent_edges == 0; }
};

/// Counts what is wrong with `mesh` and writes one note per kind of finding. Never throws
/// on bad data (empty meshes, out-of-range indices, NaN positions are counted, not fatal).
MeshReport inspect(const TriangleMesh& mesh);

/// "(0.0123, -0.0456, 0.0789) m": a position for notes and error messages.
std::string format_position(const Eigen::Vector3d& p);

}  // namespace systole::mesh
