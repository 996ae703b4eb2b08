#include "mesh/strain.h"

#include <algorithm>

namespace systole::mesh {

VertexStrain::VertexStrain(const std::vector<Eigen::Vector3d>& rest_positions,
                           const std::vector<Eigen::Vector3i>& triangles)
    : vertex_count_(static_cast<int>(rest_positions.size())), degree_(rest_positions.size(), 0) {
  std::vector<Eigen::Vector2i> all;
  all.reserve(triangles.size() * 3);
  for (const Eigen::Vector3i& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a == b || a < 0 || b < 0 || a >= vertex_count_ || b >= vertex_count_) continue;
      all.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  const auto less = [](const Eigen::Vector2i& p, const Eigen::Vector2i& q) {
    return p[0] != q[0] ? p[0] < q[0] : p[1] < q[1];
  };
  std::sort(all.begin(), all.end(), less);
  all.erase(std::unique(all.begin(), all.end()), all.end());
  for (const Eigen::Vector2i& e : all) {
    const double rest = (rest_positions[e[1]] - rest_positions[e[0]]).norm();
    if (!(rest > 0)) continue;
    edges_.push_back(e);
    rest_m_.push_back(rest);
    ++degree_[e[0]];
    ++degree_[e[1]];
  }
}

void VertexStrain::compute(const Eigen::Matrix3Xd& positions, std::vector<double>& out) const {
  out.assign(static_cast<std::size_t>(vertex_count_), 0.0);
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Eigen::Vector2i& e = edges_[i];
    const double strain = ((positions.col(e[1]) - positions.col(e[0])).norm() - rest_m_[i]) / rest_m_[i];
    out[e[0]] += strain;
    out[e[1]] += strain;
  }
  for (int v = 0; v < vertex_count_; ++v) {
    if (degree_[v] > 0) out[v] /= degree_[v];
  }
}

}  // namespace systole::mesh
