#pragma once
// The broad phase: a uniform grid of a body's triangles hashed into a table, rebuilt every
// contact step, after Teschner et al., "Optimized Spatial Hashing for Collision Detection of
// Deformable Objects" (VMV 2003): cell (i, j, k) goes to bucket (i p1 xor j p2 xor k p3) mod
// n, n about twice the triangles. The table is filled by a counting sort in triangle order,
// so each bucket's candidates ascend and are fixed by the data alone (the same at any thread
// count). Rebuilding is O(entries); a bucket may also hold triangles of other cells that
// hash alike, which the narrow phase rejects by distance.

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

  /// The triangles binned in p's cell's bucket, in increasing order (a triangle may repeat):
  /// [first, second).
  std::pair<const int*, const int*> candidates(const Eigen::Vector3d& p) const;

  /// The box of the surface, grown by reach_m. unit: m
  const Eigen::Vector3d& lower() const { return lower_; }
  const Eigen::Vector3d& upper() const { return upper_; }
  /// Whether p lies in the grown box.
  bool near(const Eigen::Vector3d& p) const {
    return (p.array() >= lower_.array()).all() && (p.array() <= upper_.array()).all();
  }

 private:
  std::size_t bucket(const Eigen::Vector3d& p) const;
  std::size_t bucket(long long ix, long long iy, long long iz) const;

  double inv_cell_ = 1;
  Eigen::Vector3d lower_ = Eigen::Vector3d::Zero(), upper_ = Eigen::Vector3d::Zero();
  std::vector<std::size_t> start_;   ///< Bucket b's triangles: [start_[b], start_[b + 1]).
  std::vector<std::size_t> fill_;    ///< Scratch of the counting sort.
  std::vector<std::pair<std::size_t, int>> entry_bucket_;  ///< (bucket, triangle) in triangle order.
  std::vector<int> triangles_;       ///< Grouped by bucket.
};

}  // namespace systole::sim::contact
