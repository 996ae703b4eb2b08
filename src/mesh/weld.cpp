#include "mesh/weld.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace systole::mesh {
namespace {

using CellKey = std::uint64_t;

// Grid cell of a coordinate, clamped so huge or tiny coordinates cannot overflow.
std::int64_t cell_of(double x, double cell_size) {
  const double c = std::floor(x / cell_size);
  constexpr double kLimit = 1e15;
  return static_cast<std::int64_t>(std::fmax(-kLimit, std::fmin(kLimit, c)));
}

CellKey hash_cell(std::int64_t x, std::int64_t y, std::int64_t z) {
  // Large odd multipliers (Teschner et al. 2003, "Optimized spatial hashing"); collisions
  // only cost a distance test, they never merge far vertices.
  return static_cast<CellKey>(x) * 73856093ULL ^ static_cast<CellKey>(y) * 19349663ULL ^
         static_cast<CellKey>(z) * 83492791ULL;
}

// Where each vertex goes: its new index, and the old index of every vertex kept.
struct WeldMap {
  std::vector<int> remap;
  std::vector<int> kept;
};

// Each vertex maps to the first earlier vertex within the tolerance (a representative),
// searched in the 27 cells around it; the first vertex of a cluster keeps its position.
WeldMap find_representatives(const std::vector<Eigen::Vector3d>& positions, double tolerance) {
  const int n = static_cast<int>(positions.size());
  // With no tolerance, only identical positions merge: a tiny cell still finds them.
  const double cell = tolerance > 0 ? tolerance : std::numeric_limits<double>::min();
  const double tol2 = tolerance * tolerance;
  std::unordered_map<CellKey, std::vector<int>> grid;
  grid.reserve(static_cast<size_t>(n));
  WeldMap map{std::vector<int>(static_cast<size_t>(n), -1), {}};
  std::vector<int>& remap = map.remap;
  std::vector<int>& kept = map.kept;
  kept.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = positions[static_cast<size_t>(i)];
    if (!p.allFinite()) {  // Never merged: inspect() and import report such data.
      remap[static_cast<size_t>(i)] = static_cast<int>(kept.size());
      kept.push_back(i);
      continue;
    }
    const std::int64_t cx = cell_of(p.x(), cell), cy = cell_of(p.y(), cell), cz = cell_of(p.z(), cell);
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy) {
        for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find(hash_cell(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (int rep : it->second) {  // Insertion order: deterministic.
            if ((positions[static_cast<size_t>(rep)] - p).squaredNorm() <= tol2) {
              found = rep;
              break;
            }
          }
        }
      }
    }
    if (found >= 0) {
      remap[static_cast<size_t>(i)] = remap[static_cast<size_t>(found)];
    } else {
      remap[static_cast<size_t>(i)] = static_cast<int>(kept.size());
      kept.push_back(i);
      grid[hash_cell(cx, cy, cz)].push_back(i);
    }
  }
  return map;
}

// The triangles in the new numbering, without those the weld collapsed.
std::vector<Eigen::Vector3i> remap_triangles(const std::vector<Eigen::Vector3i>& old, const std::vector<int>& remap) {
  const int n = static_cast<int>(remap.size());
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(old.size());
  for (const Eigen::Vector3i& t : old) {
    if ((t.array() < 0).any() || (t.array() >= n).any()) {
      triangles.push_back(Eigen::Vector3i(-1, -1, -1));  // Kept invalid: inspect() reports it.
      continue;
    }
    const Eigen::Vector3i w(remap[static_cast<size_t>(t[0])], remap[static_cast<size_t>(t[1])],
                            remap[static_cast<size_t>(t[2])]);
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) continue;  // Collapsed by the weld.
    triangles.push_back(w);
  }
  return triangles;
}

}  // namespace

double default_weld_tolerance(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : mesh.positions) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!(hi.array() >= lo.array()).all()) return 0;
  return 1e-6 * (hi - lo).norm();
}

int weld(OrganMesh& mesh, double tolerance) {
  std::vector<Eigen::Vector3d>& positions = mesh.surface.positions;
  const int n = static_cast<int>(positions.size());
  const WeldMap map = find_representatives(positions, tolerance);
  const std::vector<int>& remap = map.remap;
  const std::vector<int>& kept = map.kept;

  std::vector<Eigen::Vector3d> new_positions;
  new_positions.reserve(kept.size());
  std::vector<int> new_parts;
  const bool has_parts = mesh.vertex_part.size() == positions.size();
  for (int i : kept) {
    new_positions.push_back(positions[static_cast<size_t>(i)]);
    if (has_parts) new_parts.push_back(mesh.vertex_part[static_cast<size_t>(i)]);
  }
  // A merged vertex keeps the first one's part and belongs to every merged one's too, so a
  // part that lies on another (a valve on a chamber wall) keeps its vertices.
  if (has_parts) {
    for (int i = 0; i < n; ++i) {
      const int part = mesh.vertex_part[static_cast<size_t>(i)];
      const int into = remap[static_cast<size_t>(i)];
      if (part >= 0 && new_parts[static_cast<size_t>(into)] != part) mesh.also_in.emplace_back(into, part);
    }
  }
  for (auto& membership : mesh.also_in) {
    if (membership.first >= 0 && membership.first < n) membership.first = remap[static_cast<size_t>(membership.first)];
  }

  std::vector<Eigen::Vector3i> triangles = remap_triangles(mesh.surface.triangles, remap);

  const int removed = n - static_cast<int>(kept.size());
  positions = std::move(new_positions);
  mesh.surface.triangles = std::move(triangles);
  if (has_parts) mesh.vertex_part = std::move(new_parts);
  mesh.normalize_membership();
  return removed;
}

}  // namespace systole::mesh