#include "mesh/mesh.h"

#include <algorithm>

namespace systole::mesh {

int OrganMesh::part_index(const std::string& name) const {
  for (int i = 0; i < static_cast<int>(part_names.size()); ++i) {
    if (part_names[i] == name) return i;
  }
  return -1;
}

std::vector<char> OrganMesh::part_mask(int part) const {
  std::vector<char> mask(surface.positions.size(), 0);
  for (std::size_t v = 0; v < mask.size() && v < vertex_part.size(); ++v) mask[v] = vertex_part[v] == part;
  for (const auto& [v, p] : also_in) {
    if (p == part && v >= 0 && static_cast<std::size_t>(v) < mask.size()) mask[static_cast<std::size_t>(v)] = 1;
  }
  return mask;
}

TriangleMesh OrganMesh::part_surface(int part) const {
  const std::vector<char> mask = part_mask(part);
  TriangleMesh out;
  out.positions = surface.positions;
  for (const Eigen::Vector3i& t : surface.triangles) {
    const auto in = [&](int v) { return v >= 0 && static_cast<std::size_t>(v) < mask.size() && mask[static_cast<std::size_t>(v)]; };
    if (in(t[0]) && in(t[1]) && in(t[2])) out.triangles.push_back(t);
  }
  return out;
}

void OrganMesh::normalize_membership() {
  std::erase_if(also_in, [&](const std::pair<int, int>& m) {
    return m.first < 0 || (static_cast<std::size_t>(m.first) < vertex_part.size() &&
                           vertex_part[static_cast<std::size_t>(m.first)] == m.second);
  });
  std::sort(also_in.begin(), also_in.end());
  also_in.erase(std::unique(also_in.begin(), also_in.end()), also_in.end());
}

}  // namespace systole::mesh
