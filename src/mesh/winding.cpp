#include "mesh/winding.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace systole::mesh {
namespace {

/// The ray's direction: oblique to the axes and to a generator's symmetry planes.
const Eigen::Vector3d kRay = Eigen::Vector3d(0.3141, 0.5772, 0.7548).normalized();

/// Positions in the ray's frame: (u, v) across the ray, w along it.
struct RayFrame {
  Eigen::Vector3d u = kRay.unitOrthogonal(), v = kRay.cross(u);  // u x v = kRay
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return {u.dot(x), v.dot(x), kRay.dot(x)}; }
};

/// Twice the signed area of (a, b, q) across the ray: positive with q left of a -> b.
double orient(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& q) {
  return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
}

/// The sign of orient(a, b, q), exactly: in doubles where their rounding cannot flip it
/// (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust geometric
/// predicates", Discrete Comput Geom 18:305, orient2d's first bound), else in 113-bit
/// arithmetic, where the differences and products of doubles are exact and the last
/// difference rounds without changing its sign. Exact signs keep the triangles round a corner
/// covering the plane once however near the corner a point falls.
int orient_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& q) {
  const double left = (b[0] - a[0]) * (q[1] - a[1]), right = (b[1] - a[1]) * (q[0] - a[0]);
  const double det = left - right;
  constexpr double kBound = 3.3306690738754716e-16;  // (3 + 16 eps) eps, eps = 2^-53.
  if (std::abs(det) > kBound * (std::abs(left) + std::abs(right))) return det > 0 ? 1 : -1;
  using Wide = __float128;
  const Wide exact = (Wide(b[0]) - Wide(a[0])) * (Wide(q[1]) - Wide(a[1])) - (Wide(b[1]) - Wide(a[1])) * (Wide(q[0]) - Wide(a[0]));
  return exact > 0 ? 1 : exact < 0 ? -1 : 0;
}

/// Triangles binned by their extent across the ray in a square grid of cells.
struct Grid {
  double lo_u = 0, lo_v = 0, cell = 1;
  int size = 1;
  std::vector<int> start, triangles;  ///< Cell c holds triangles[start[c] .. start[c + 1]).

  int cell_of(double x, double lo) const { return static_cast<int>(std::floor((x - lo) / cell)); }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < size && j < size; }
};

Grid bin(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3i>& triangles) {
  Grid g;
  if (triangles.empty()) return g;
  double lo_u = HUGE_VAL, lo_v = HUGE_VAL, hi_u = -HUGE_VAL, hi_v = -HUGE_VAL;
  for (const Eigen::Vector3i& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      lo_u = std::min(lo_u, p[t[k]][0]), hi_u = std::max(hi_u, p[t[k]][0]);
      lo_v = std::min(lo_v, p[t[k]][1]), hi_v = std::max(hi_v, p[t[k]][1]);
    }
  }
  g.size = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(triangles.size()))));
  g.lo_u = lo_u, g.lo_v = lo_v;
  g.cell = std::max({hi_u - lo_u, hi_v - lo_v, 1e-12}) / g.size * (1 + 1e-9);
  // Two passes: count each cell's triangles, then place them.
  std::vector<int> count(static_cast<std::size_t>(g.size) * g.size + 1, 0);
  auto each_cell = [&](const Eigen::Vector3i& t, auto&& visit) {
    const double a = std::min({p[t[0]][0], p[t[1]][0], p[t[2]][0]}), b = std::max({p[t[0]][0], p[t[1]][0], p[t[2]][0]});
    const double c = std::min({p[t[0]][1], p[t[1]][1], p[t[2]][1]}), d = std::max({p[t[0]][1], p[t[1]][1], p[t[2]][1]});
    const int i0 = std::max(0, g.cell_of(a, g.lo_u)), i1 = std::min(g.size - 1, g.cell_of(b, g.lo_u));
    const int j0 = std::max(0, g.cell_of(c, g.lo_v)), j1 = std::min(g.size - 1, g.cell_of(d, g.lo_v));
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) visit(j * g.size + i);
    }
  };
  for (const Eigen::Vector3i& t : triangles) each_cell(t, [&](int c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  g.start = count;
  g.triangles.resize(static_cast<std::size_t>(count.back()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    each_cell(triangles[t], [&](int c) { g.triangles[count[c]++] = static_cast<int>(t); });
  }
  return g;
}

/// The signed crossing of the ray from q with triangle (a, b, c): +1 leaving through its
/// front, -1 entering, 0 missing it. A point on an edge belongs to the triangle for which it
/// is a top or left edge (turned counter-clockwise): the rasterizer's rule, which is moving
/// the point a hair along +u, so the two triangles sharing an edge never both take it, nor
/// both miss it, and a fan round a corner takes it once.
int crossing(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3i& t, const Eigen::Vector3d& q) {
  const int turn = orient_sign(p[t[0]], p[t[1]], p[t[2]]);
  if (turn == 0) return 0;  // Edge-on to the ray: its neighbours count.
  double side[3];
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& from = p[t[(k + 1) % 3]];  // The edge facing corner k.
    const Eigen::Vector3d& to = p[t[(k + 2) % 3]];
    const int sign = turn * orient_sign(from, to, q);
    if (sign < 0) return 0;
    if (sign == 0) {
      const double du = turn * (to[0] - from[0]), dv = turn * (to[1] - from[1]);
      if (!(dv < 0 || (dv == 0 && du > 0))) return 0;
    }
    side[k] = std::max(0.0, turn * orient(from, to, q));
  }
  const double sum = side[0] + side[1] + side[2];
  const double w = sum > 0 ? (side[0] * p[t[0]][2] + side[1] * p[t[1]][2] + side[2] * p[t[2]][2]) / sum : p[t[0]][2];
  if (w <= q[2]) return 0;  // Behind the point.
  return turn;
}

}  // namespace

const Eigen::Vector3d& winding_ray() { return kRay; }

std::vector<int> winding_numbers(const Eigen::Matrix3Xd& positions, const std::vector<Eigen::Vector3i>& triangles,
                                 const Eigen::Matrix3Xd& points) {
  const RayFrame frame;
  std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(positions.cols()));
  for (Eigen::Index i = 0; i < positions.cols(); ++i) p[i] = frame(positions.col(i));
  const Grid grid = bin(p, triangles);
  std::vector<int> winding(static_cast<std::size_t>(points.cols()), 0);
  for (Eigen::Index k = 0; k < points.cols(); ++k) {
    const Eigen::Vector3d q = frame(points.col(k));
    const int i = grid.cell_of(q[0], grid.lo_u), j = grid.cell_of(q[1], grid.lo_v);
    if (triangles.empty() || !grid.inside(i, j)) continue;
    const int c = j * grid.size + i;
    for (int n = grid.start[c]; n < grid.start[c + 1]; ++n) winding[k] += crossing(p, triangles[grid.triangles[n]], q);
  }
  return winding;
}

}  // namespace systole::mesh
