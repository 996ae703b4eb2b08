#pragma once
// The broad phase: a uniform grid of a body's triangles, rebuilt every contact step, after
// Teschner et al., "Optimized Spatial Hashing for Collision Detection of Deformable
// Objects" (VMV 2003). Instead of a fixed-size hash table the (cell, triangle) entries are
// sorted, so a query is a binary search and the order of candidates is fixed by the data
// alone: the same triangles in the same order at any thread count. Rebuilding costs
// O(T log T), about what refitting a BVH costs for a body that deforms everywhere.

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace systole::sim::contact {

class TriangleGrid {
 public:
  /// Bins every triangle of surface y into the cells its box, grown by reach_m, overlaps;
  /// cells are cell_m on a side. A point within reach_m of a triangle then finds it in the
  /// point's own cell.
  void build(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles, double cell_m, double reach_m);

  /// The triangles binned in p's cell, in increasing order: [first, second).
  std::pair<const int*, const int*> candidates(const Eigen::Vector3d& p) const;

  /// The box of the surface, grown by reach_m. unit: m
  const Eigen::Vector3d& lower() const { return lower_; }
  const Eigen::Vector3d& upper() const { return upper_; }
  /// Whether p lies in the grown box.
  bool near(const Eigen::Vector3d& p) const {
    return (p.array() >= lower_.array()).all() && (p.array() <= upper_.array()).all();
  }

 private:
  std::uint64_t key(const Eigen::Vector3d& p) const;
  std::uint64_t key(long long ix, long long iy, long long iz) const;

  double inv_cell_ = 1;
  Eigen::Vector3d lower_ = Eigen::Vector3d::Zero(), upper_ = Eigen::Vector3d::Zero();
  std::vector<std::pair<std::uint64_t, int>> entries_;  ///< (cell key, triangle), sorted.
  std::vector<std::uint64_t> keys_;                     ///< entries_' keys, for the search.
  std::vector<int> triangles_;                          ///< entries_' triangles.
};

}  // namespace systole::sim::contact
