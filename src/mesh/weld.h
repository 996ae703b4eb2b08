#pragma once
// Welding: vertices closer than a tolerance become one, so file formats that split
// vertices at seams (STL, OBJ with normals) give a connected surface.

#include "mesh/mesh.h"

namespace systole::mesh {

/// Merges vertices closer than `tolerance` (same unit as the positions): the merged vertex
/// belongs to the first vertex's part first and to every other merged vertex's part too
/// (OrganMesh::also_in); drops triangles that collapse. Returns the number of vertices removed.
/// Deterministic: the result depends only on the input order.
int weld(OrganMesh& mesh, double tolerance);

/// A tolerance relative to the mesh size: 1e-6 of the bounding-box diagonal.
double default_weld_tolerance(const TriangleMesh& mesh);

}  // namespace systole::mesh
