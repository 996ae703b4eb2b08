#pragma once
// Meshing an implicit surface into a closed, manifold, well-shaped triangle mesh.
//
// A subdivided icosahedron is cast onto the surface along rays from a centre (a closed
// genus-0 start, whatever the shape), then isotropic remeshing (Botsch & Kobbelt 2004,
// "A remeshing approach to multiresolution modeling"): split long edges, collapse short
// ones under the link condition, flip edges towards valence 6, relax tangentially and
// project back onto the surface. Every step keeps the mesh closed and manifold; all of it
// runs on one thread in a fixed order, so the result is deterministic.

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/procedural/sdf.h"

namespace systole::mesh::procedural {

struct MesherSettings {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< Inside the surface; rays start here. unit: m
  double bound_radius = 0.2;   ///< The whole surface lies within this distance of `center`. unit: m
  int target_triangles = 5000;  ///< About how many triangles the result has.
  int iterations = 8;           ///< Remeshing rounds.
};

/// The surface where `field` is zero. The result has no parts; the caller assigns them.
/// Throws Error(kInternal) if the field has no surface around `center`.
TriangleMesh mesh_implicit_surface(const Field& field, const MesherSettings& settings);

}  // namespace systole::mesh::procedural
