#include "sim/contact/spatial_hash.h"

#include <algorithm>
#include <cmath>

namespace systole::sim::contact {

std::size_t TriangleGrid::bucket(long long ix, long long iy, long long iz) const {
  // Teschner et al. 2003, §4: the three large primes, XOR-ed, modulo the table size.
  const std::uint64_t h = (static_cast<std::uint64_t>(ix) * 73856093ull) ^ (static_cast<std::uint64_t>(iy) * 19349663ull) ^
                          (static_cast<std::uint64_t>(iz) * 83492791ull);
  return static_cast<std::size_t>(h % (start_.size() - 1));
}

std::size_t TriangleGrid::bucket(const Eigen::Vector3d& p) const {
  return bucket(static_cast<long long>(std::floor(p.x() * inv_cell_)), static_cast<long long>(std::floor(p.y() * inv_cell_)),
                static_cast<long long>(std::floor(p.z() * inv_cell_)));
}

void TriangleGrid::build(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles, double cell_m,
                         double reach_m) {
  inv_cell_ = 1.0 / cell_m;
  if (y.cols() == 0) {
    lower_.setZero();
    upper_.setZero();
  } else {
    lower_ = y.rowwise().minCoeff().array() - reach_m;
    upper_ = y.rowwise().maxCoeff().array() + reach_m;
  }
  // Buckets: about two per triangle, plus the one-past-the-end offset.
  start_.assign(2 * triangles.size() + 2, 0);
  entry_bucket_.clear();
  const auto cell = [&](double v) { return static_cast<long long>(std::floor(v * inv_cell_)); };
  // Counting sort by bucket: one pass counts, a prefix sum places, a second pass fills in
  // triangle order, so each bucket's triangles ascend (deterministic, O(entries)).
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3i& tri = triangles[t];
    const Eigen::Vector3d lo = y.col(tri[0]).cwiseMin(y.col(tri[1])).cwiseMin(y.col(tri[2])).array() - reach_m;
    const Eigen::Vector3d hi = y.col(tri[0]).cwiseMax(y.col(tri[1])).cwiseMax(y.col(tri[2])).array() + reach_m;
    for (long long ix = cell(lo.x()); ix <= cell(hi.x()); ++ix)
      for (long long iy = cell(lo.y()); iy <= cell(hi.y()); ++iy)
        for (long long iz = cell(lo.z()); iz <= cell(hi.z()); ++iz) {
          const std::size_t b = bucket(ix, iy, iz);
          entry_bucket_.emplace_back(b, static_cast<int>(t));
          ++start_[b + 1];
        }
  }
  for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
  triangles_.resize(entry_bucket_.size());
  fill_.assign(start_.begin(), start_.end() - 1);
  for (const auto& [b, t] : entry_bucket_) triangles_[fill_[b]++] = t;
}

std::pair<const int*, const int*> TriangleGrid::candidates(const Eigen::Vector3d& p) const {
  if (start_.size() < 2) return {nullptr, nullptr};
  const std::size_t b = bucket(p);
  const int* base = triangles_.data();
  return {base + start_[b], base + start_[b + 1]};
}

}  // namespace systole::sim::contact
