#include <cstddef>

#include "mesh/procedural/implicit_mesher.h"
#include "mesh/procedural/organs.h"

namespace systole::mesh::procedural {

OrganMesh mesh_organ_surface(const Field& field, const Eigen::Vector3d& center, double bound_radius_m, int detail,
                             std::span<const char* const> part_names,
                             const std::function<int(const Eigen::Vector3d& x, int part)>& refine) {
  MesherSettings settings;
  settings.center = center;
  settings.bound_radius = bound_radius_m;
  settings.target_triangles = target_triangles(detail);

  OrganMesh mesh;
  mesh.surface = mesh_implicit_surface(field, settings);
  mesh.part_names.assign(part_names.begin(), part_names.end());
  mesh.vertex_part.reserve(mesh.surface.positions.size());
  for (const Eigen::Vector3d& x : mesh.surface.positions)
    mesh.vertex_part.push_back(refine(x, field.primitives[static_cast<std::size_t>(field.nearest_primitive(x))].part));
  return mesh;
}

}  // namespace systole::mesh::procedural
