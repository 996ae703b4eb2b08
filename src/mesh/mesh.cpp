#include "mesh/mesh.h"

#include <algorithm>

namespace systole::mesh {

int OrganMesh::part_index(const std::string& name) const {
  for (int i = 0; i < static_cast<int>(part_names.size()); ++i) {
    if (part_names[i] == name) return i;
  }
  return -1;
}

std::vector<int> OrganMesh::parts_named(const std::string& name) const {
  if (const int exact = part_index(name); exact >= 0) return {exact};
  // Whole trailing segments only: "atrium" must not find "heart/left_atrium".
  const std::string tail = "/" + name;
  std::vector<int> found;
  for (int i = 0; i < static_cast<int>(part_names.size()); ++i) {
    if (part_names[i].ends_with(tail)) found.push_back(i);
  }
  return found;
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

std::vector<TriangleMesh> OrganMesh::part_surfaces() const {
  const std::size_t n = surface.positions.size();
  // Each vertex's parts: its first, then its others (also_in is sorted by vertex).
  std::vector<std::vector<int>> parts_of(n);
  for (std::size_t v = 0; v < n && v < vertex_part.size(); ++v) {
    if (vertex_part[v] >= 0) parts_of[v].push_back(vertex_part[v]);
  }
  for (const auto& [v, p] : also_in) {
    if (v >= 0 && static_cast<std::size_t>(v) < n) parts_of[static_cast<std::size_t>(v)].push_back(p);
  }
  for (auto& of : parts_of) {  // A pair may repeat a first part when not normalized.
    std::sort(of.begin(), of.end());
    of.erase(std::unique(of.begin(), of.end()), of.end());
  }
  std::vector<TriangleMesh> out(part_names.size());
  const auto in = [&](int v, int part) {
    if (v < 0 || static_cast<std::size_t>(v) >= n) return false;
    const auto& of = parts_of[static_cast<std::size_t>(v)];
    return std::find(of.begin(), of.end(), part) != of.end();
  };
  for (const Eigen::Vector3i& t : surface.triangles) {
    if (t[0] < 0 || static_cast<std::size_t>(t[0]) >= n) continue;
    for (const int part : parts_of[static_cast<std::size_t>(t[0])]) {
      if (part < 0 || static_cast<std::size_t>(part) >= out.size() || !in(t[1], part) || !in(t[2], part)) continue;
      out[static_cast<std::size_t>(part)].triangles.push_back(t);
    }
  }
  // Each part over its own vertices, kept in the surface's order.
  std::vector<int> own(n, -1);
  for (TriangleMesh& part : out) {
    std::vector<int> used;
    for (const Eigen::Vector3i& t : part.triangles) used.insert(used.end(), {t[0], t[1], t[2]});
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    for (std::size_t k = 0; k < used.size(); ++k) {
      own[static_cast<std::size_t>(used[k])] = static_cast<int>(k);
      part.positions.push_back(surface.positions[static_cast<std::size_t>(used[k])]);
    }
    for (Eigen::Vector3i& t : part.triangles) t = {own[t[0]], own[t[1]], own[t[2]]};
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
