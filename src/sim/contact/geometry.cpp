#include "sim/contact/geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace systole::sim::contact {

namespace {

// One region's answer: the corner weights, the feature and which edge or corner it is.
ClosestPoint closest_at(const Eigen::Vector3d& bary, Feature feature, int index) {
  ClosestPoint out;
  out.bary = bary;
  out.feature = feature;
  out.index = index;
  return out;
}

}  // namespace

ClosestPoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return closest_at({1, 0, 0}, Feature::kCorner, 0);
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return closest_at({0, 1, 0}, Feature::kCorner, 1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return closest_at({1 - v, v, 0}, Feature::kEdge, 0);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return closest_at({0, 0, 1}, Feature::kCorner, 2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return closest_at({1 - w, 0, w}, Feature::kEdge, 2);  // Edge c-a: corners 2 and 0.
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return closest_at({0, 1 - w, w}, Feature::kEdge, 1);
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return closest_at({1, 0, 0}, Feature::kCorner, 0);  // A degenerate triangle: its first corner.
  const double v = vb / denom, w = vc / denom;
  return closest_at({1 - v - w, v, w}, Feature::kFace, 0);
}

std::vector<Eigen::Vector3i> edge_neighbours(const std::vector<Eigen::Vector3i>& triangles, int vertex_count) {
  // Directed edges sorted by their undirected key: a manifold edge appears exactly twice.
  struct Half {
    long long key;
    int triangle, edge;
  };
  std::vector<Half> halves;
  halves.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
      const long long key = static_cast<long long>(std::min(i, j)) * vertex_count + std::max(i, j);
      halves.push_back({key, static_cast<int>(t), k});
    }
  }
  std::sort(halves.begin(), halves.end(), [](const Half& l, const Half& r) {
    return l.key != r.key ? l.key < r.key : l.triangle != r.triangle ? l.triangle < r.triangle : l.edge < r.edge;
  });
  std::vector<Eigen::Vector3i> out(triangles.size(), Eigen::Vector3i(-1, -1, -1));
  for (std::size_t q = 0; q < halves.size();) {
    std::size_t end = q;
    while (end < halves.size() && halves[end].key == halves[q].key) ++end;
    if (end - q == 2) {
      out[halves[q].triangle][halves[q].edge] = halves[q + 1].triangle;
      out[halves[q + 1].triangle][halves[q + 1].edge] = halves[q].triangle;
    }
    q = end;
  }
  return out;
}

void pseudo_normals(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles,
                    Eigen::Matrix3Xd& face_normal, Eigen::Matrix3Xd& vertex_normal) {
  face_normal.resize(3, static_cast<Eigen::Index>(triangles.size()));
  vertex_normal.setZero(3, y.cols());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3i& tri = triangles[t];
    const Eigen::Vector3d n = (y.col(tri[1]) - y.col(tri[0])).cross(y.col(tri[2]) - y.col(tri[0]));
    const double len = n.norm();
    const Eigen::Vector3d unit = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
    face_normal.col(static_cast<Eigen::Index>(t)) = unit;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e1 = y.col(tri[(k + 1) % 3]) - y.col(tri[k]);
      const Eigen::Vector3d e2 = y.col(tri[(k + 2) % 3]) - y.col(tri[k]);
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      vertex_normal.col(tri[k]) += angle * unit;
    }
  }
}

Eigen::Vector3d feature_normal(const ClosestPoint& cp, int t, const std::vector<Eigen::Vector3i>& triangles,
                               const std::vector<Eigen::Vector3i>& neighbours, const Eigen::Matrix3Xd& face_normal,
                               const Eigen::Matrix3Xd& vertex_normal) {
  switch (cp.feature) {
    case Feature::kFace: return face_normal.col(t);
    case Feature::kEdge: {
      const int across = neighbours[t][cp.index];
      return across >= 0 ? Eigen::Vector3d(face_normal.col(t) + face_normal.col(across)) : Eigen::Vector3d(face_normal.col(t));
    }
    case Feature::kCorner: return vertex_normal.col(triangles[t][cp.index]);
  }
  return face_normal.col(t);
}

double winding_number(const Eigen::Vector3d& p, const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles) {
  double sum = 0;
  for (const Eigen::Vector3i& t : triangles) {
    const Eigen::Vector3d a = y.col(t[0]) - p, b = y.col(t[1]) - p, c = y.col(t[2]) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2.0 * std::atan2(numerator, denominator);
  }
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace systole::sim::contact
