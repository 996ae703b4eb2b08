#include "sim/reduced.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "mesh/normals.h"

namespace systole::sim {
namespace {

using Point = std::array<int, 3>;  ///< A point of the finest lattice, in finest voxel edges.

/// Corner k (bit 0: x, bit 1: y, bit 2: z) of the voxel with lowest corner `lo` and edge `size`.
Point corner(const Point& lo, int size, int k) {
  return {lo[0] + size * (k & 1), lo[1] + size * ((k >> 1) & 1), lo[2] + size * ((k >> 2) & 1)};
}

/// The voxel shell over a surface: coarse voxels of edge `coarse_m` holding the surface,
/// each split into detail^3 voxels; everything in units of the finest voxel edge.
struct Lattice {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< unit: m
  double coarse_m = 0;                               ///< unit: m
  int finest = 1;                                    ///< Finest voxel edges per coarse voxel (max detail).
  std::map<Point, int> coarse_detail;                ///< Occupied coarse voxels and their detail.
  std::map<Point, int> voxel_size;                   ///< Every voxel: lowest corner -> edge (finest units).
  std::map<Point, int> node_of;                      ///< Voxel corner -> particle index.
  std::vector<Point> nodes;

  double fine_m() const { return coarse_m / finest; }
  Point coarse_cell(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d u = (p - origin) / coarse_m;
    return {int(std::floor(u[0])), int(std::floor(u[1])), int(std::floor(u[2]))};
  }
  Eigen::Vector3d position(const Point& q) const { return origin + fine_m() * Eigen::Vector3d(q[0], q[1], q[2]); }
  int node(const Point& q) {
    auto [it, added] = node_of.try_emplace(q, static_cast<int>(nodes.size()));
    if (added) nodes.push_back(q);
    return it->second;
  }
};

int region_detail(const OrganParams& organ, int region) { return region >= 0 ? organ.regions[region].detail : 1; }

/// Marks the coarse voxels the surface passes through, with the finest detail of the
/// regions there: every vertex, and points over every triangle no farther apart than
/// half a finest voxel, so a long triangle marks every voxel it crosses.
void mark_surface(const OrganParams& organ, const mesh::OrganGeometry& geometry, Lattice& lat) {
  const auto& surface = geometry.mesh.surface;
  auto mark = [&](const Eigen::Vector3d& p, int detail) {
    int& d = lat.coarse_detail[lat.coarse_cell(p)];
    d = std::max(d, detail);
  };
  auto region_of = [&](int v) { return geometry.vertex_region.empty() ? -1 : geometry.vertex_region[v]; };
  for (const auto& t : surface.triangles) {
    int detail = 1;
    for (int k = 0; k < 3; ++k) detail = std::max(detail, region_detail(organ, region_of(t[k])));
    const Eigen::Vector3d a = surface.positions[t[0]], b = surface.positions[t[1]], c = surface.positions[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int steps = std::max(1, static_cast<int>(std::ceil(longest / (0.5 * lat.fine_m()))));
    for (int i = 0; i <= steps; ++i) {
      for (int j = 0; i + j <= steps; ++j) mark(a + (b - a) * (double(i) / steps) + (c - a) * (double(j) / steps), detail);
    }
  }
  for (std::size_t v = 0; v < surface.positions.size(); ++v) mark(surface.positions[v], region_detail(organ, region_of(int(v))));
}

/// Splits every occupied coarse voxel into detail^3 voxels and numbers their corners.
void make_voxels(Lattice& lat) {
  for (const auto& [cell, detail] : lat.coarse_detail) {
    const int size = lat.finest / detail;
    for (int i = 0; i < detail * detail * detail; ++i) {
      const Point lo{cell[0] * lat.finest + size * (i % detail), cell[1] * lat.finest + size * (i / detail % detail),
                     cell[2] * lat.finest + size * (i / (detail * detail))};
      lat.voxel_size[lo] = size;
      for (int k = 0; k < 8; ++k) lat.node(corner(lo, size, k));
    }
  }
}

/// Springs: every pair of a voxel's corners (12 edges, 12 face and 4 body diagonals, so a
/// voxel resists shear), and every corner of a finer voxel lying on a coarser voxel's
/// boundary (a hanging node) tied to that voxel's corners, so the two resolutions move
/// together.
std::vector<std::pair<int, int>> lattice_springs(Lattice& lat) {
  std::vector<std::pair<int, int>> springs;
  for (const auto& [lo, size] : lat.voxel_size) {
    int corners[8];
    for (int k = 0; k < 8; ++k) corners[k] = lat.node_of.at(corner(lo, size, k));
    for (int p = 0; p < 8; ++p) {
      for (int q = p + 1; q < 8; ++q) springs.emplace_back(std::min(corners[p], corners[q]), std::max(corners[p], corners[q]));
    }
    if (size == 1) continue;
    for (int i = 0; i <= size; ++i) {
      for (int j = 0; j <= size; ++j) {
        for (int k = 0; k <= size; ++k) {
          const int ends = (i == 0 || i == size) + (j == 0 || j == size) + (k == 0 || k == size);
          if (ends == 0 || ends == 3) continue;  // Inside the voxel, or one of its corners.
          const auto found = lat.node_of.find({lo[0] + i, lo[1] + j, lo[2] + k});
          if (found == lat.node_of.end()) continue;
          for (int c : corners) springs.emplace_back(std::min(c, found->second), std::max(c, found->second));
        }
      }
    }
  }
  std::sort(springs.begin(), springs.end());
  springs.erase(std::unique(springs.begin(), springs.end()), springs.end());
  return springs;
}

/// Each vertex in the voxel that holds it, with trilinear weights.
Embedding embed_vertices(const std::vector<Eigen::Vector3d>& positions, const Lattice& lat) {
  Embedding e;
  e.node.resize(8, static_cast<Eigen::Index>(positions.size()));
  e.weight.resize(8, static_cast<Eigen::Index>(positions.size()));
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const int size = lat.finest / lat.coarse_detail.at(lat.coarse_cell(positions[v]));
    const Eigen::Vector3d u = (positions[v] - lat.origin) / (lat.fine_m() * size);
    const Point lo{size * int(std::floor(u[0])), size * int(std::floor(u[1])), size * int(std::floor(u[2]))};
    const Eigen::Vector3d f = u - Eigen::Vector3d(lo[0], lo[1], lo[2]) / size;
    for (int k = 0; k < 8; ++k) {
      e.node(k, v) = lat.node_of.at(corner(lo, size, k));
      e.weight(k, v) = ((k & 1) ? f[0] : 1 - f[0]) * ((k & 2) ? f[1] : 1 - f[1]) * ((k & 4) ? f[2] : 1 - f[2]);
    }
  }
  return e;
}

/// The outer faces of the filled coarse voxels (occupied, or enclosed by occupied ones),
/// as outward triangles on the coarse corners: the lattice's closed hull.
std::vector<Eigen::Vector3i> hull_triangles(const Lattice& lat) {
  Point lo{0, 0, 0}, hi{0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    lo[a] = lat.coarse_detail.begin()->first[a];
    hi[a] = lo[a];
  }
  for (const auto& [cell, detail] : lat.coarse_detail) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], cell[a] - 1);
      hi[a] = std::max(hi[a], cell[a] + 1);
    }
  }
  // Flood the outside from a corner of the padded box.
  std::map<Point, bool> outside;
  std::vector<Point> stack{lo};
  outside[lo] = true;
  while (!stack.empty()) {
    const Point p = stack.back();
    stack.pop_back();
    for (int a = 0; a < 3; ++a) {
      for (int s : {-1, 1}) {
        Point q = p;
        q[a] += s;
        if (q[a] < lo[a] || q[a] > hi[a] || lat.coarse_detail.count(q) || outside.count(q)) continue;
        outside[q] = true;
        stack.push_back(q);
      }
    }
  }
  std::vector<Eigen::Vector3i> triangles;
  for (const auto& [cell, detail] : lat.coarse_detail) {
    for (int a = 0; a < 3; ++a) {
      for (int s : {-1, 1}) {
        Point q = cell;
        q[a] += s;
        if (!outside.count(q)) continue;
        const int u = (a + 1) % 3, w = (a + 2) % 3;
        int quad[4];
        const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
        for (int k = 0; k < 4; ++k) {
          Point c{cell[0] * lat.finest, cell[1] * lat.finest, cell[2] * lat.finest};
          if (s > 0) c[a] += lat.finest;
          c[u] += du[k] * lat.finest;
          c[w] += dw[k] * lat.finest;
          quad[k] = lat.node_of.at(c);
        }
        // (u, w) counter-clockwise faces +a (e_u x e_w = e_a); the -a face turns the other way.
        if (s > 0) {
          triangles.emplace_back(quad[0], quad[1], quad[2]);
          triangles.emplace_back(quad[0], quad[2], quad[3]);
        } else {
          triangles.emplace_back(quad[0], quad[2], quad[1]);
          triangles.emplace_back(quad[0], quad[3], quad[2]);
        }
      }
    }
  }
  return triangles;
}

double surface_area(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles) {
  double area = 0;
  for (const auto& t : triangles) area += 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
  return area;
}

}  // namespace

Eigen::Vector3d embed_vertex(const Embedding& e, const Eigen::Matrix3Xd& x, int v) {
  if (e.empty()) return x.col(v);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 8; ++k) p += e.weight(k, v) * x.col(e.node(k, v));
  return e.offset.cols() ? Eigen::Vector3d(p + e.offset.col(v)) : p;
}

void embed(const Embedding& e, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) {
  if (e.empty()) {
    out = x;
    return;
  }
  out.resize(3, e.vertex_count());
  for (int v = 0; v < e.vertex_count(); ++v) out.col(v) = embed_vertex(e, x, v);
}

namespace {

// Mass: each vertex's lumped mass goes to its voxel's corners by its weights; a corner no
// vertex weighs on (rare) still needs a mass, so every corner has a tenth of the mean.
// Region: the one whose vertices weigh most on the node; normal: their weighted mean
// (returned, for matching the stiffness).
Eigen::Matrix3Xd weigh_nodes(const OrganParams& organ, const mesh::OrganGeometry& geometry, const Eigen::Matrix3Xd& rest,
                             const Embedding& e, BodyParts& parts) {
  const auto& surface = geometry.mesh.surface;
  const int vertex_count = static_cast<int>(surface.positions.size());
  const int n = static_cast<int>(parts.rest_positions.cols());
  const Eigen::VectorXd vertex_mass = lumped_masses(rest, surface.triangles, organ.body.mass_kg);
  parts.mass_kg = Eigen::VectorXd::Constant(n, 0.1 * organ.body.mass_kg / n);
  const int region_count = static_cast<int>(organ.regions.size());
  Eigen::MatrixXd region_weight = Eigen::MatrixXd::Zero(region_count + 1, n);
  std::vector<float> vertex_normal(3 * static_cast<std::size_t>(vertex_count));
  mesh::vertex_normals(rest.data(), vertex_count, surface.triangles, vertex_normal.data());
  Eigen::Matrix3Xd node_normal = Eigen::Matrix3Xd::Zero(3, n);
  for (int v = 0; v < vertex_count; ++v) {
    const int r = geometry.vertex_region.empty() ? -1 : geometry.vertex_region[v];
    const Eigen::Vector3d normal(vertex_normal[3 * v], vertex_normal[3 * v + 1], vertex_normal[3 * v + 2]);
    for (int k = 0; k < 8; ++k) {
      const int i = e.node(k, v);
      const double w = e.weight(k, v);
      parts.mass_kg[i] += 0.9 * w * vertex_mass[v];
      region_weight(r + 1, i) += w;
      node_normal.col(i) += w * normal;
    }
  }
  parts.particle_region.resize(n);
  for (int i = 0; i < n; ++i) {
    Eigen::Index best = 0;
    if (region_weight.col(i).maxCoeff(&best) <= 0) best = 0;
    parts.particle_region[i] = static_cast<int>(best) - 1;
  }
  return node_normal;
}

// Stiffness matched to the surface network's energy under in-plane stretch: the scale of
// the lattice springs' stiffness.
double matched_stiffness_scale(const Eigen::Matrix3Xd& rest, const std::vector<Eigen::Vector3i>& triangles,
                               const BodyParts& parts, const Eigen::Matrix3Xd& node_normal) {
  double surface_energy = 0;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) surface_energy += 0.5 * (rest.col(t[k]) - rest.col(t[(k + 1) % 3])).squaredNorm();
  }
  double lattice_energy = 0;
  for (const auto& [a, b] : parts.springs) {
    const Eigen::Vector3d d = parts.rest_positions.col(b) - parts.rest_positions.col(a);
    const Eigen::Vector3d normal = node_normal.col(a) + node_normal.col(b);
    // With no surface nearby, the mean of (1 - cos^2)^2 over all directions: 8/15.
    const double in_plane = normal.norm() > 1e-9 ? 1.0 - std::pow(normal.normalized().dot(d.normalized()), 2) : std::sqrt(8.0 / 15.0);
    lattice_energy += d.squaredNorm() * in_plane * in_plane;
  }
  return lattice_energy > 0 ? surface_energy / lattice_energy : 1.0;
}

}  // namespace

ReducedBody build_reduced_model(const OrganParams& organ, const mesh::OrganGeometry& geometry,
                                const ModelOptions& options) {
  const auto& surface = geometry.mesh.surface;
  const int vertex_count = static_cast<int>(surface.positions.size());
  Eigen::Matrix3Xd rest(3, vertex_count);
  for (int v = 0; v < vertex_count; ++v) rest.col(v) = surface.positions[v];
  const Eigen::Vector3d lo = rest.rowwise().minCoeff(), hi = rest.rowwise().maxCoeff();

  // Whole coarse voxels centred on the bounding box, one more than fits, so no vertex
  // lies on the lattice's outer boundary.
  Lattice lat;
  lat.coarse_m = (hi - lo).maxCoeff() / organ.body.lattice;
  for (const auto& r : organ.regions) lat.finest = std::max(lat.finest, r.detail);
  const Eigen::Vector3d cells = ((hi - lo) / lat.coarse_m).array().floor() + 1.0;
  lat.origin = 0.5 * (lo + hi) - 0.5 * lat.coarse_m * cells;
  mark_surface(organ, geometry, lat);
  make_voxels(lat);

  BodyParts parts;
  parts.springs = lattice_springs(lat);
  parts.stretch_count = static_cast<int>(parts.springs.size());
  const int n = static_cast<int>(lat.nodes.size());
  parts.rest_positions.resize(3, n);
  for (int i = 0; i < n; ++i) parts.rest_positions.col(i) = lat.position(lat.nodes[i]);

  ReducedBody body;
  body.voxels = static_cast<int>(lat.voxel_size.size());
  body.embedding = embed_vertices(surface.positions, lat);
  const Embedding& e = body.embedding;
  const Eigen::Matrix3Xd node_normal = weigh_nodes(organ, geometry, rest, e, parts);
  const double scale = matched_stiffness_scale(rest, surface.triangles, parts, node_normal);
  parts.spring_stiffness_N_per_m.assign(parts.springs.size(), scale * organ.body.stiffness_N_per_m);

  if (geometry.report.encloses_volume() && !lat.coarse_detail.empty()) {
    parts.volume_triangles = hull_triangles(lat);
    // The hull lies outside the surface: the same inward motion changes its volume by
    // (hull area / surface area) times as much. Rescaled so the pressure energy
    // (K / V0) dV^2 / 2 and the driven volume change match the surface's.
    const double area_ratio = surface_area(parts.rest_positions, parts.volume_triangles) / surface_area(rest, surface.triangles);
    const double volume_ratio = enclosed_volume(parts.rest_positions, parts.volume_triangles) / enclosed_volume(rest, surface.triangles);
    parts.volume_stiffness_scale = volume_ratio / (area_ratio * area_ratio);
    parts.volume_drive_scale = area_ratio / volume_ratio;
  }
  parts.interaction_reach_m = 0.5 * std::sqrt(3.0) * lat.coarse_m;
  body.model = build_model(organ, std::move(parts), options);
  return body;
}

}  // namespace systole::sim
