#pragma once
// Meshing an implicit surface into a closed, manifold, well-shaped triangle mesh.
//
// The surface must be star-shaped about a centre: every ray from the centre leaves it
// once. Each vertex is then a direction plus the distance where its ray leaves the
// surface, so the mesh is a triangulation of the sphere carried onto the surface; as
// long as every spherical triangle keeps its orientation the result is embedded, closed
// and outward-facing, whatever the remeshing does. A subdivided icosahedron starts it;
// isotropic remeshing (Botsch & Kobbelt 2004, "A remeshing approach to multiresolution
// modeling") then splits long edges, collapses short ones under the link condition, flips
// edges towards valence 6 and relaxes vertices towards their area-weighted centroids,
// all measured on the surface. One thread, fixed order: deterministic.

#include <Eigen/Core>
#include <functional>
#include <span>

#include "mesh/mesh.h"
#include "mesh/procedural/sdf.h"

namespace systole::mesh::procedural {

struct MesherSettings {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< The surface is star-shaped about it. unit: m
  double bound_radius = 0.2;   ///< The whole surface lies within this distance of `center`. unit: m
  int target_triangles = 5000;  ///< About how many triangles the result has.
  int iterations = 8;           ///< Remeshing rounds.
};

/// The surface where `field` is zero. The result has no parts; the caller assigns them.
/// Throws Error(kInternal) if the field has no surface around `center`.
TriangleMesh mesh_implicit_surface(const Field& field, const MesherSettings& settings);

/// The tail the single-surface organs share: meshes `field` about `center` (within
/// `bound_radius_m`) at `detail` (1..6), names the parts, and gives each vertex the part of
/// its nearest primitive as `refine(x, part)` adjusts it (poles, lobes by side, the apex).
OrganMesh mesh_organ_surface(const Field& field, const Eigen::Vector3d& center, double bound_radius_m, int detail,
                             std::span<const char* const> part_names,
                             const std::function<int(const Eigen::Vector3d& x, int part)>& refine);

}  // namespace systole::mesh::procedural
