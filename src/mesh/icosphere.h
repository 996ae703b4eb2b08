#pragma once
// A geodesic sphere: the test and benchmark body of the simulator (uniform, closed,
// well-shaped, with a size that doubles per level).

#include "mesh/mesh.h"

namespace systole::mesh {

/// Icosahedron subdivided `levels` times and projected onto a sphere of `radius_m`:
/// 10 * 4^levels + 2 vertices, outward counter-clockwise triangles. Deterministic.
TriangleMesh icosphere(double radius_m, int levels);

}  // namespace systole::mesh
