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
  int degenerate_triangles = 0;  ///< Zero area or repeated vertex index.
  int boundary_edges = 0;        ///< Edges with one triangle: the surface is open.
  int nonmanifold_edges = 0;     ///< Edges with three or more triangles.
  int inconsistent_edges = 0;    ///< Edges whose two triangles disagree on orientation.
  int components = 0;            ///< Connected pieces.
  double volume_m3 = 0;          ///< Signed enclosed volume (meaningful when closed).
  std::vector<std::string> notes;  ///< One line per finding, with an example location.

  bool closed() const { return boundary_edges == 0 && nonmanifold_edges == 0; }
  bool clean() const { return closed() && degenerate_triangles == 0 && inconsistent_edges == 0; }
};

MeshReport inspect(const TriangleMesh& mesh);

}  // namespace systole::mesh
