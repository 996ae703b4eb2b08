#include "sim/contact/spatial_hash.h"

#include <algorithm>
#include <cmath>

namespace systole::sim::contact {

std::uint64_t TriangleGrid::key(long long ix, long long iy, long long iz) const {
  // 21 bits per axis: two million cells a side, far beyond any scene's extent over its cell.
  constexpr std::uint64_t mask = (1ull << 21) - 1;
  return ((static_cast<std::uint64_t>(ix) & mask) << 42) | ((static_cast<std::uint64_t>(iy) & mask) << 21) |
         (static_cast<std::uint64_t>(iz) & mask);
}

std::uint64_t TriangleGrid::key(const Eigen::Vector3d& p) const {
  return key(static_cast<long long>(std::floor(p.x() * inv_cell_)), static_cast<long long>(std::floor(p.y() * inv_cell_)),
             static_cast<long long>(std::floor(p.z() * inv_cell_)));
}

void TriangleGrid::build(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles, double cell_m,
                         double reach_m) {
  inv_cell_ = 1.0 / cell_m;
  entries_.clear();
  if (y.cols() == 0) {
    lower_.setZero();
    upper_.setZero();
  } else {
    lower_ = y.rowwise().minCoeff().array() - reach_m;
    upper_ = y.rowwise().maxCoeff().array() + reach_m;
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3i& tri = triangles[t];
    const Eigen::Vector3d lo = y.col(tri[0]).cwiseMin(y.col(tri[1])).cwiseMin(y.col(tri[2])).array() - reach_m;
    const Eigen::Vector3d hi = y.col(tri[0]).cwiseMax(y.col(tri[1])).cwiseMax(y.col(tri[2])).array() + reach_m;
    const auto cell = [&](double v) { return static_cast<long long>(std::floor(v * inv_cell_)); };
    for (long long ix = cell(lo.x()); ix <= cell(hi.x()); ++ix)
      for (long long iy = cell(lo.y()); iy <= cell(hi.y()); ++iy)
        for (long long iz = cell(lo.z()); iz <= cell(hi.z()); ++iz) entries_.emplace_back(key(ix, iy, iz), static_cast<int>(t));
  }
  std::sort(entries_.begin(), entries_.end());
  keys_.resize(entries_.size());
  triangles_.resize(entries_.size());
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    keys_[e] = entries_[e].first;
    triangles_[e] = entries_[e].second;
  }
}

std::pair<const int*, const int*> TriangleGrid::candidates(const Eigen::Vector3d& p) const {
  const std::uint64_t k = key(p);
  const auto range = std::equal_range(keys_.begin(), keys_.end(), k);
  const int* base = triangles_.data();
  return {base + (range.first - keys_.begin()), base + (range.second - keys_.begin())};
}

}  // namespace systole::sim::contact
