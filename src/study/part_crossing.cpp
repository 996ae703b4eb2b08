#include "study/part_crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace systole::study {
namespace {

std::uint64_t key(int vertex, int part) { return (std::uint64_t(std::uint32_t(vertex)) << 32) | std::uint32_t(part); }

/// The point of triangle abc nearest to p, and whether it lies inside the triangle rather
/// than on an edge or a corner (Ericson, Real-Time Collision Detection, 5.1.5).
Eigen::Vector3d nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c, bool& inside) {
  inside = false;
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  inside = true;
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

PartCrossingWatch::PartCrossingWatch(const mesh::OrganMesh& mesh, double band_m) : band_m_(band_m) {
  const auto& tris = mesh.surface.triangles;
  const int parts = static_cast<int>(mesh.part_names.size());
  // Which parts each triangle is in (all three corners in the part).
  std::vector<std::vector<int>> triangle_in(tris.size());
  std::vector<std::vector<char>> masks(parts);
  std::vector<long> size(parts, 0);
  for (int p = 0; p < parts; ++p) {
    masks[p] = mesh.part_mask(p);
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const auto& f = tris[t];
      if (masks[p][f[0]] && masks[p][f[1]] && masks[p][f[2]]) {
        triangle_in[t].push_back(p);
        ++size[p];
      }
    }
  }
  // shared(a, b): triangles in both. A part is checked unless another part's triangles are
  // a strict subset of its own (a group, a material) or the same as an earlier part's.
  std::vector<long> shared(std::size_t(parts) * parts, 0);
  for (const auto& in : triangle_in) {
    for (int a : in) {
      for (int b : in) ++shared[std::size_t(a) * parts + b];
    }
  }
  std::vector<int> checked_index(parts, -1);
  for (int p = 0; p < parts; ++p) {
    bool keep = size[p] > 0;
    for (int q = 0; q < parts && keep; ++q) {
      if (q == p || size[q] == 0 || shared[std::size_t(q) * parts + p] != size[q]) continue;  // q not within p
      keep = !(size[q] < size[p] || q < p);  // q strictly within p, or p repeats q
    }
    if (!keep) continue;
    checked_index[p] = static_cast<int>(part_names_.size());
    part_names_.push_back(mesh.part_names[p]);
  }
  if (part_names_.size() < 2) return;

  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (int p : triangle_in[t]) {
      if (checked_index[p] < 0) continue;
      triangles_.push_back(tris[t]);
      triangle_part_.push_back(checked_index[p]);
      break;
    }
  }
  const int vertices = static_cast<int>(mesh.surface.positions.size());
  vertex_parts_.resize(vertices);
  for (int p = 0; p < parts; ++p) {
    if (checked_index[p] < 0) continue;
    for (int v = 0; v < vertices; ++v) {
      if (masks[p][v]) vertex_parts_[v].push_back(checked_index[p]);
    }
  }
  rest_.resize(3, vertices);
  for (int v = 0; v < vertices; ++v) rest_.col(v) = mesh.surface.positions[v];
  bin(rest_, band_m_, rest_grid_);
  stamp_.assign(triangles_.size(), 0);
}

void PartCrossingWatch::bin(const Eigen::Matrix3Xd& x, double cell_m, Grid& g) const {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& f : triangles_) {
    for (int k = 0; k < 3; ++k) {
      lo = lo.cwiseMin(x.col(f[k]));
      hi = hi.cwiseMax(x.col(f[k]));
    }
  }
  // Coarser cells for parts spread far apart, so the grid stays small.
  g.cell_m = std::max(cell_m, (hi - lo).maxCoeff() / 256);
  g.min = lo - Eigen::Vector3d::Constant(g.cell_m);
  g.size = (((hi - lo) / g.cell_m).array().floor().cast<int>() + 3).matrix();
  const auto cell_of = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3i c = ((p - g.min) / g.cell_m).array().floor().cast<int>();
    return c.cwiseMax(0).cwiseMin(g.size - Eigen::Vector3i::Ones()).eval();
  };
  const std::size_t cells = std::size_t(g.size.x()) * g.size.y() * g.size.z();
  g.start.assign(cells + 1, 0);
  // Two passes over each triangle's box of cells: count, then fill.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t c = 0; c < cells; ++c) g.start[c + 1] += g.start[c];
      g.triangles.resize(g.start[cells]);
      g.fill.assign(g.start.begin(), g.start.end() - 1);
    }
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const auto& f = triangles_[t];
      const Eigen::Vector3d a = x.col(f[0]), b = x.col(f[1]), c = x.col(f[2]);
      const Eigen::Vector3i from = cell_of(a.cwiseMin(b).cwiseMin(c)), to = cell_of(a.cwiseMax(b).cwiseMax(c));
      for (int k = from.z(); k <= to.z(); ++k) {
        for (int j = from.y(); j <= to.y(); ++j) {
          for (int i = from.x(); i <= to.x(); ++i) {
            const std::size_t cell = (std::size_t(k) * g.size.y() + j) * g.size.x() + i;
            if (pass == 0) {
              ++g.start[cell + 1];
            } else {
              g.triangles[g.fill[cell]++] = static_cast<int>(t);
            }
          }
        }
      }
    }
  }
}

template <class Found>
void PartCrossingWatch::near_parts(const Grid& grid, const Eigen::Matrix3Xd& x, int v, double radius_m, int only,
                                   Found&& found) const {
  struct Nearest {
    int part;
    double distance, side;
  };
  Nearest nearest[16];
  int count = 0;
  const Eigen::Vector3d p = x.col(v);
  const Eigen::Vector3i at = ((p - grid.min) / grid.cell_m).array().floor().cast<int>();
  const int reach = static_cast<int>(std::ceil(radius_m / grid.cell_m));
  ++stamp_now_;
  const auto& own = vertex_parts_[v];
  for (int k = at.z() - reach; k <= at.z() + reach; ++k) {
    for (int j = at.y() - reach; j <= at.y() + reach; ++j) {
      for (int i = at.x() - reach; i <= at.x() + reach; ++i) {
        if (i < 0 || j < 0 || k < 0 || i >= grid.size.x() || j >= grid.size.y() || k >= grid.size.z()) continue;
        const std::size_t cell = (std::size_t(k) * grid.size.y() + j) * grid.size.x() + i;
        for (int n = grid.start[cell]; n < grid.start[cell + 1]; ++n) {
          const int t = grid.triangles[n];
          if (stamp_[t] == stamp_now_) continue;
          stamp_[t] = stamp_now_;
          const int part = triangle_part_[t];
          if (only >= 0 && part != only) continue;
          if (std::find(own.begin(), own.end(), part) != own.end()) continue;
          const auto& f = triangles_[t];
          const Eigen::Vector3d a = x.col(f[0]), b = x.col(f[1]), c = x.col(f[2]);
          bool inside = false;
          const Eigen::Vector3d q = nearest_on_triangle(p, a, b, c, inside);
          const double distance = (p - q).norm();
          if (distance > radius_m) continue;
          const double side =
              inside ? (p - q).dot((b - a).cross(c - a).normalized()) : std::numeric_limits<double>::quiet_NaN();
          int slot = 0;
          while (slot < count && nearest[slot].part != part) ++slot;
          if (slot == count) {
            if (count == 16) continue;  // More parts within the band than any real organ has.
            nearest[count++] = {part, distance, side};
          } else if (distance < nearest[slot].distance) {
            nearest[slot] = {part, distance, side};
          }
        }
      }
    }
  }
  for (int s = 0; s < count; ++s) found(nearest[s].part, nearest[s].side);
}

void PartCrossingWatch::check(const Eigen::Matrix3Xd& positions, int frame) {
  if (part_names_.size() < 2) return;
  // A vertex within the band of a part now was within band + its motion + the part's
  // motion of it at rest: that is how far its rest side is looked for.
  const double moved = (positions - rest_).colwise().norm().maxCoeff();
  bin(positions, band_m_, grid_);
  for (int v = 0; v < static_cast<int>(vertex_parts_.size()); ++v) {
    if (vertex_parts_[v].empty()) continue;
    near_parts(grid_, positions, v, band_m_, -1, [&](int part, double side) {
      auto at_rest = rest_side_.find(key(v, part));
      if (at_rest == rest_side_.end()) {
        double rest_side = std::numeric_limits<double>::quiet_NaN();
        near_parts(rest_grid_, rest_, v, band_m_ + 2 * moved, part, [&](int, double s) { rest_side = s; });
        at_rest = rest_side_.emplace(key(v, part), rest_side).first;
      }
      if (std::isnan(side) || std::isnan(at_rest->second) || (side > 0) == (at_rest->second > 0)) return;
      if (std::abs(side) <= worst_.depth_m) return;
      worst_ = {std::abs(side), v, part_names_[vertex_parts_[v].front()], part_names_[part], frame};
    });
  }
}

}  // namespace systole::study
