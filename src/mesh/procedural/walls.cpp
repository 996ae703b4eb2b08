#include "mesh/procedural/walls.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "common/spline.h"

namespace systole::mesh::procedural {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

double tet_volume(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  return std::abs((b - a).dot((c - a).cross(d - a))) / 6.0;
}

/// A cell's volume: a hexahedron (corner bits: around, along, across) as six tetrahedra
/// about its diagonal; a prism (a pole's wedge: three corners, then the same three across) as three.
double cell_volume(const std::vector<Vec>& x) {
  if (x.size() == 8) {
    static const int kTets[6][2] = {{1, 3}, {3, 2}, {2, 6}, {6, 4}, {4, 5}, {5, 1}};
    double v = 0;
    for (const auto& t : kTets) v += tet_volume(x[0], x[t[0]], x[t[1]], x[7]);
    return v;
  }
  return tet_volume(x[0], x[1], x[2], x[3]) + tet_volume(x[1], x[2], x[3], x[4]) + tet_volume(x[2], x[3], x[4], x[5]);
}

}  // namespace

Wall::Wall(HeartBuilder& builder, WallShape shape, const PartsAt& parts) : builder_(builder), shape_(std::move(shape)) {
  const int keys = static_cast<int>(shape_.height.size());
  rows_ = (keys - 1) * shape_.rows_per_key;
  first_node_ = -1;
  index_ = builder_.begin_wall();
  add_nodes(parts);
  add_cells();
  draw_rows_ = (keys - 1) * shape_.draw_rows_per_key + 1;
  add_drawn_vertices(parts);
  add_surfaces();
}

// Lattice nodes: layer by layer, pole, rings, pole (a tube: rings only).
void Wall::add_nodes(const PartsAt& parts) {
  const int columns = shape_.columns, layers = shape_.layers;
  for (int k = 0; k <= layers; ++k) {
    for (int r = 0; r <= rows_; ++r) {
      const bool pole = !shape_.tube && (r == 0 || r == rows_);
      for (int c = 0; c < (pole ? 1 : columns); ++c) {
        const WallPoint p{kTwoPi * c / columns, double(r) / rows_, double(k) / layers};
        Vec circumferential, along, normal;
        frame(p, circumferential, along, normal);
        Vec fibre = circumferential;
        if (shape_.helix_rad) {
          const double helix = shape_.helix_rad(p.across, p.along);
          fibre = std::cos(helix) * circumferential + std::sin(helix) * normal.cross(circumferential);
        }
        const double cross = shape_.cross_fibre ? shape_.cross_fibre(p.across, p.along) : 0.0;
        const int n = builder_.add_node(point(p), parts(p, false), fibre, normal, cross, bool(shape_.helix_rad), index_, p);
        if (first_node_ < 0) first_node_ = n;
      }
    }
  }
}

// Cells: hexahedra, and wedges round the poles.
void Wall::add_cells() {
  const int columns = shape_.columns, layers = shape_.layers;
  for (int k = 0; k < layers; ++k) {
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c < columns; ++c) {
        const int c1 = (c + 1) % columns;
        const bool first = !shape_.tube && r == 0, last = !shape_.tube && r == rows_ - 1;
        if (first || last) {
          const int pole = node(k, first ? 0 : rows_, 0), pole_out = node(k + 1, first ? 0 : rows_, 0);
          const int ring = first ? 1 : rows_ - 1;
          builder_.add_cell({pole, node(k, ring, c), node(k, ring, c1), pole_out, node(k + 1, ring, c), node(k + 1, ring, c1)});
        } else {
          std::vector<int> corners(8);
          for (int b = 0; b < 8; ++b) corners[b] = node(k + (b >> 2 & 1), r + (b >> 1 & 1), (b & 1) ? c1 : c);
          builder_.add_cell(corners);
        }
      }
    }
  }
}

// Drawn surfaces: the lining (across 0) and the outside (across 1), each vertex carried by
// the lattice nodes round it.
void Wall::add_drawn_vertices(const PartsAt& parts) {
  const int draw_columns = shape_.draw_columns;
  drawn_.assign(2 * draw_rows_ * draw_columns, -1);
  for (int across = 0; across < 2; ++across) {
    for (int r = 0; r < draw_rows_; ++r) {
      const bool pole = !shape_.tube && (r == 0 || r == draw_rows_ - 1);
      for (int c = 0; c < draw_columns; ++c) {
        int& v = drawn_[(across * draw_rows_ + r) * draw_columns + c];
        if (pole && c > 0) {
          v = drawn_[(across * draw_rows_ + r) * draw_columns];
          continue;
        }
        const WallPoint p{kTwoPi * c / draw_columns, draw_along(r), double(across)};
        std::array<int, 8> nodes;
        std::array<double, 8> weights;
        carriers(p, nodes, weights);
        v = builder_.add_vertex(point(p), parts(p, true), nodes, weights);
      }
    }
  }
}

// Triangles facing out of the muscle: the outside away from the axis, the lining into the blood.
void Wall::add_surfaces() {
  const int draw_columns = shape_.draw_columns;
  lining_band_.resize(draw_rows_ - 1);
  auto add_rim = [&](int a, int b, int c, const Vec& out) {
    if (const auto added = builder_.add_triangle_facing(a, b, c, out)) triangles_.push_back(*added);
  };
  // By index, not by shape, so the surfaces stay consistently turned where a thick wall
  // bends sharply (the atrioventricular groove): with e2 = axis x e1, (along, around) turns
  // the outside outwards, and the lining the other way.
  for (int across = 0; across < 2; ++across) {
    for (int r = 0; r + 1 < draw_rows_; ++r) {
      for (int c = 0; c < draw_columns; ++c) {
        const int c1 = (c + 1) % draw_columns;
        const int quad[2][3] = {{drawn(across, r, c), drawn(across, r + 1, c), drawn(across, r, c1)},
                                {drawn(across, r, c1), drawn(across, r + 1, c), drawn(across, r + 1, c1)}};
        for (const auto& t : quad) {
          if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
          const Eigen::Vector3i triangle = across == 1 ? Eigen::Vector3i(t[0], t[1], t[2]) : Eigen::Vector3i(t[0], t[2], t[1]);
          builder_.add_triangle(triangle[0], triangle[1], triangle[2]);
          triangles_.push_back(triangle);
          if (across == 0) lining_band_[r].push_back(triangle);
        }
      }
    }
  }
  if (shape_.tube) {  // The two rims join lining and outside.
    for (int end = 0; end < 2; ++end) {
      const int r = end == 0 ? 0 : draw_rows_ - 1;
      for (int c = 0; c < draw_columns; ++c) {
        const int c1 = (c + 1) % draw_columns;
        Vec t, m, normal;
        frame({kTwoPi * c / draw_columns, draw_along(r), 0.5}, t, m, normal);
        const Vec out = end == 0 ? Vec(-m) : m;
        add_rim(drawn(0, r, c), drawn(1, r, c), drawn(0, r, c1), out);
        add_rim(drawn(0, r, c1), drawn(1, r, c), drawn(1, r, c1), out);
      }
    }
  }
}

int Wall::node(int layer, int row, int column) const {
  const int columns = shape_.columns;
  if (shape_.tube) return first_node_ + layer * (rows_ + 1) * columns + row * columns + column;
  const int per_layer = 2 + (rows_ - 1) * columns;
  const int base = first_node_ + layer * per_layer;
  if (row == 0) return base;
  if (row == rows_) return base + 1 + (rows_ - 1) * columns;
  return base + 1 + (row - 1) * columns + column;
}

int Wall::drawn(int across, int row, int column) const {
  return drawn_[(across * draw_rows_ + row) * shape_.draw_columns + (column % shape_.draw_columns)];
}

double Wall::key_value(const std::vector<double>& keys, double along, bool odd) const {
  const int n = static_cast<int>(keys.size());
  const double u = std::clamp(along, 0.0, 1.0) * (n - 1);
  const int i = std::min(static_cast<int>(u), n - 2);
  // The neighbour beyond an end: straight on for a tube, mirrored at a pole.
  auto ghost = [&](int end, int inner) {
    if (shape_.tube) return 2 * keys[end] - keys[inner];
    return odd ? -keys[inner] : keys[inner];
  };
  const double p0 = i > 0 ? keys[i - 1] : ghost(0, 1);
  const double p3 = i + 2 < n ? keys[i + 2] : ghost(n - 1, n - 2);
  return catmull_rom(p0, keys[i], keys[i + 1], p3, u - i);
}

double Wall::key_slope(const std::vector<double>& keys, double along, bool odd) const {
  const double h = 1e-4;
  const double a = std::max(0.0, along - h), b = std::min(1.0, along + h);
  return (key_value(keys, b, odd) - key_value(keys, a, odd)) / (b - a);
}

void Wall::meridian(double along, double& height, double& radius, double& thickness, Eigen::Vector2d& normal) const {
  height = key_value(shape_.height, along, false);
  radius = key_value(shape_.radius, along, true);
  thickness = std::max(0.0012, key_value(shape_.thickness, along, false));
  // The outward normal of the meridian (radius, height): the tangent turned a quarter.
  normal = Eigen::Vector2d(-key_slope(shape_.height, along, false), key_slope(shape_.radius, along, true)).normalized();
}

double Wall::lining_radius(double around, double along) const {
  double height, radius, thickness;
  Eigen::Vector2d normal;
  meridian(along, height, radius, thickness, normal);
  if (radius <= 0 || !shape_.shape_radius) return std::max(0.0, radius);
  return shape_.shape_radius(around, along, radius, thickness);
}

Vec Wall::outward(double around, double along, const Eigen::Vector2d& normal) const {
  const Vec radial = std::cos(around) * shape_.e1 + std::sin(around) * shape_.e2;
  const Vec straight = normal[0] * radial + normal[1] * shape_.axis;
  if (!shape_.shift && !shape_.shape_radius) return straight;
  // The lining's own normal where the wall is shaped (a flattened face, the septum, a groove)
  // or its axis bent: laid along the meridian's normal instead, a wall leans across itself
  // where its radius changes round it, its cells skewed and the wall thinned by the cosine of
  // the lean (44 deg, 3.5 -> 2.5 mm, on the right ventricle's sternocostal face), and the
  // drive's shear tips such cells over until the lining passes through the outside.
  const double h = 1e-4, a = std::max(0.0, along - h), b = std::min(1.0, along + h);
  const double lining = shape_.shape_radius ? lining_radius(around, along) : 0.0;
  double meridian_radius, unused_height, unused_thickness;
  Eigen::Vector2d unused_normal;
  meridian(along, unused_height, meridian_radius, unused_thickness, unused_normal);
  // Along the meridian, its tangent with the shift's slope, its radius' slope scaled as the
  // lining's radius is against the meridian's: exact for a wall shaped in proportion, and
  // where the septum holds the lining far inside the meridian, its wall does not copy the
  // meridian's waist at the annulus (the slope of the shaped radius itself, taken over any
  // step, folded the outside at the septum's ends).
  const double scale = lining > 0 && meridian_radius > 1e-9 ? std::min(2.0, lining / meridian_radius) : 1.0;
  Vec tangent = (key_value(shape_.height, b, false) - key_value(shape_.height, a, false)) / (b - a) * shape_.axis +
                scale * (key_value(shape_.radius, b, true) - key_value(shape_.radius, a, true)) / (b - a) * radial;
  if (shape_.shift) tangent += (shape_.shift(b) - shape_.shift(a)) / (b - a);
  const Vec circumferential = -std::sin(around) * shape_.e1 + std::cos(around) * shape_.e2;
  Vec turning = circumferential;
  if (lining > 0) {
    // Round the wall, the lining's slope over a drawn column either side: a crease between
    // two columns (where a face or a groove meets the round wall) turns the wall along the
    // crease's bisector, not along whichever side's slope the column falls on. Faded out
    // over the first key interval from a pole, where a lopsided cap (the right ventricle's
    // apex, its septal side flattened) would turn each ring its own way and dimple the
    // outside at the pole.
    const double step = kTwoPi / shape_.draw_columns;
    const double key = 1.0 / (static_cast<double>(shape_.height.size()) - 1);
    const double fade = shape_.tube ? 1.0 : std::clamp(std::min(along, 1 - along) / key, 0.0, 1.0);
    turning = lining * circumferential +
              fade * (lining_radius(around + step, along) - lining_radius(around - step, along)) / (2 * step) * radial;
  }
  Vec n = tangent.cross(turning);
  if (n.norm() < 1e-12) return straight;  // A pole: the axis' own direction.
  n.normalize();
  return n.dot(straight) < 0 ? Vec(-n) : n;
}

Vec Wall::point(const WallPoint& p) const {
  double height, radius, thickness;
  Eigen::Vector2d normal;
  meridian(p.along, height, radius, thickness, normal);
  const Vec radial = std::cos(p.around) * shape_.e1 + std::sin(p.around) * shape_.e2;
  const double lining = lining_radius(p.around, p.along);
  const Vec bend = shape_.shift ? shape_.shift(p.along) : Vec::Zero();
  return shape_.origin + height * shape_.axis + lining * radial + bend + p.across * thickness * outward(p.around, p.along, normal);
}

void Wall::frame(const WallPoint& p, Vec& circumferential, Vec& meridian_dir, Vec& normal) const {
  double height, radius, thickness;
  Eigen::Vector2d n2;
  meridian(p.along, height, radius, thickness, n2);
  normal = outward(p.around, p.along, n2).normalized();
  circumferential = -std::sin(p.around) * shape_.e1 + std::cos(p.around) * shape_.e2;
  circumferential = (circumferential - circumferential.dot(normal) * normal).normalized();
  meridian_dir = normal.cross(circumferential);
}

void Wall::carriers(const WallPoint& p, std::array<int, 8>& nodes, std::array<double, 8>& weights) const {
  nodes.fill(first_node_);
  weights.fill(0);
  const int columns = shape_.columns;
  const double u = std::clamp(p.along, 0.0, 1.0) * rows_;
  const int r = std::min(static_cast<int>(u), rows_ - 1);
  const double fr = u - r;
  double around = std::fmod(p.around, kTwoPi);
  if (around < 0) around += kTwoPi;
  const double x = around / kTwoPi * columns;
  const int c = std::min(static_cast<int>(x), columns - 1), c1 = (c + 1) % columns;
  const double fc = x - c;
  const double y = p.across * shape_.layers;
  const int k = std::clamp(static_cast<int>(std::floor(y)), 0, shape_.layers - 1);
  const double fk = y - k;  // Outside [0, 1] a point off the wall follows the nearest cell linearly.
  int slot = 0;
  auto put = [&](int n, double w) { nodes[slot] = n, weights[slot] = w, ++slot; };
  for (int layer = 0; layer < 2; ++layer) {
    const double wk = layer == 0 ? 1 - fk : fk;
    if (!shape_.tube && r == 0) {
      put(node(k + layer, 0, 0), wk * (1 - fr));
      put(node(k + layer, 1, c), wk * fr * (1 - fc));
      put(node(k + layer, 1, c1), wk * fr * fc);
    } else if (!shape_.tube && r == rows_ - 1) {
      put(node(k + layer, r, c), wk * (1 - fr) * (1 - fc));
      put(node(k + layer, r, c1), wk * (1 - fr) * fc);
      put(node(k + layer, rows_, 0), wk * fr);
    } else {
      put(node(k + layer, r, c), wk * (1 - fr) * (1 - fc));
      put(node(k + layer, r, c1), wk * (1 - fr) * fc);
      put(node(k + layer, r + 1, c), wk * fr * (1 - fc));
      put(node(k + layer, r + 1, c1), wk * fr * fc);
    }
  }
}

std::vector<int> Wall::outside_nodes() const {
  std::vector<int> out;
  for (int r = 0; r <= rows_; ++r) {
    const bool pole = !shape_.tube && (r == 0 || r == rows_);
    for (int c = 0; c < (pole ? 1 : shape_.columns); ++c) out.push_back(node(shape_.layers, r, c));
  }
  return out;
}

std::vector<int> Wall::nodes_near(const Vec& x, double reach, int at_most, bool outside_only) const {
  std::vector<std::pair<double, int>> near;
  const int last = node(shape_.layers, rows_, shape_.columns - 1);
  for (int n = outside_only ? node(shape_.layers, 0, 0) : first_node_; n <= last; ++n) {
    const double d = (builder_.node_position(n) - x).norm();
    if (d <= reach) near.emplace_back(d, n);
  }
  std::sort(near.begin(), near.end());
  std::vector<int> out;
  for (std::size_t i = 0; i < near.size() && static_cast<int>(i) < at_most; ++i) out.push_back(near[i].second);
  return out;
}

std::vector<Eigen::Vector3i> Wall::lining(int from_row, int to_row) const {
  std::vector<Eigen::Vector3i> out;
  for (int r = from_row; r < to_row; ++r) out.insert(out.end(), lining_band_[r].begin(), lining_band_[r].end());
  return out;
}

double Wall::outside_radius_at(double height, double around) const {
  // The outside's meridian at `around`, sampled finely once; its first crossing of the plane.
  if (outside_meridian_.empty()) {
    const int samples = 400;
    for (int i = 0; i <= samples; ++i) {
      const double along = double(i) / samples;
      double h, radius, thickness;
      Eigen::Vector2d normal;
      meridian(along, h, radius, thickness, normal);
      const double lining = radius <= 0 ? 0.0 : lining_radius(around, along);
      outside_meridian_.emplace_back(h + thickness * normal[1], lining + thickness * normal[0]);
    }
  }
  for (std::size_t i = 1; i < outside_meridian_.size(); ++i) {
    const auto [h0, r0] = outside_meridian_[i - 1];
    const auto [h1, r1] = outside_meridian_[i];
    if ((h0 - height) * (h1 - height) <= 0 && h0 != h1) return r0 + (height - h0) / (h1 - h0) * (r1 - r0);
  }
  return 0;
}

HeartBuilder::HeartBuilder(std::vector<std::string> part_names) { mesh_.part_names = std::move(part_names); }

std::optional<Eigen::Vector3i> HeartBuilder::add_triangle_facing(int a, int b, int c, const Vec& out) {
  if (a == b || b == c || a == c) return std::nullopt;
  const Vec& pa = vertex_position(a);
  const Vec n = (vertex_position(b) - pa).cross(vertex_position(c) - pa);
  if (n.dot(out) < 0) std::swap(b, c);
  add_triangle(a, b, c);
  return Eigen::Vector3i(a, b, c);
}

int HeartBuilder::part(const std::string& name) const { return mesh_.part_index(name); }

int HeartBuilder::add_node(const Vec& x, const std::vector<int>& parts, const Vec& fibre, const Vec& normal,
                           double cross_fibre, bool active, int wall, const WallPoint& at) {
  Myocardium& m = mesh_.anatomy.myocardium;
  m.node_wall.push_back(wall);
  m.node_along.push_back(at.along);
  m.node_depth.push_back(at.across);
  for (std::size_t i = 1; i < parts.size(); ++i) m.node_also_in.emplace_back(static_cast<int>(m.nodes.size()), parts[i]);
  m.nodes.push_back(x);
  m.node_part.push_back(parts.front());
  m.node_volume_m3.push_back(0);
  fibre_.push_back(fibre);
  normal_.push_back(normal);
  cross_fibre_.push_back(cross_fibre);
  active_.push_back(active);
  return static_cast<int>(m.nodes.size()) - 1;
}

void HeartBuilder::add_cell(const std::vector<int>& corners) { cells_.push_back(corners); }

int HeartBuilder::add_vertex(const Vec& x, const std::vector<int>& parts, const std::array<int, 8>& nodes,
                             const std::array<double, 8>& weights) {
  const int v = static_cast<int>(mesh_.surface.positions.size());
  mesh_.surface.positions.push_back(x);
  mesh_.vertex_part.push_back(parts.front());
  for (std::size_t i = 1; i < parts.size(); ++i) mesh_.also_in.emplace_back(v, parts[i]);
  mesh_.anatomy.myocardium.vertex_nodes.push_back(nodes);
  mesh_.anatomy.myocardium.vertex_weights.push_back(weights);
  return v;
}

OrganMesh HeartBuilder::finish() {
  Myocardium& m = mesh_.anatomy.myocardium;
  // Every pair of a cell's corners is a spring; it gets its share of the cell's volume.
  std::map<std::pair<int, int>, double> share;
  for (const std::vector<int>& cell : cells_) {
    std::vector<Vec> x;
    for (int n : cell) x.push_back(m.nodes[n]);
    const double volume = cell_volume(x);
    const int pairs = static_cast<int>(cell.size() * (cell.size() - 1) / 2);
    for (std::size_t i = 0; i < cell.size(); ++i) {
      m.node_volume_m3[cell[i]] += volume / cell.size();
      for (std::size_t j = i + 1; j < cell.size(); ++j) {
        share[std::minmax(cell[i], cell[j])] += volume / pairs;
      }
    }
  }
  double total = 0;
  for (const auto& [pair, volume] : share) {
    const double length = (m.nodes[pair.first] - m.nodes[pair.second]).norm();
    m.springs.push_back(pair);
    m.spring_weight.push_back(volume / (length * length));
    total += m.spring_weight.back();
  }
  const double mean = total / static_cast<double>(m.springs.size());
  for (double& w : m.spring_weight) w /= mean;
  const std::size_t cell_springs = m.springs.size();
  for (const auto& [a, b] : glue_) {
    if (share.count(std::minmax(a, b))) continue;
    m.springs.emplace_back(a, b);
    m.spring_weight.push_back(2.0);
  }
  // Fibre and sheet-normal shares where the spring lies: the mean of its ends' directions.
  for (std::size_t j = 0; j < m.springs.size(); ++j) {
    const auto [a, b] = m.springs[j];
    if (!active_[a] || !active_[b] || j >= cell_springs) {
      m.fibre_share.push_back(-1);  // Passive: contracts evenly if its region is driven.
      m.normal_share.push_back(0);
      m.cross_fibre.push_back(0);
      continue;
    }
    const Vec d = (m.nodes[b] - m.nodes[a]).normalized();
    const Vec normal = (normal_[a] + normal_[b]).normalized();
    Vec fibre = fibre_[a] + (fibre_[a].dot(fibre_[b]) < 0 ? -1.0 : 1.0) * fibre_[b];
    fibre = (fibre - fibre.dot(normal) * normal).normalized();  // In the wall, as at either end.
    m.fibre_share.push_back(std::pow(fibre.dot(d), 2));
    m.normal_share.push_back(std::pow(normal.dot(d), 2));
    m.cross_fibre.push_back(0.5 * (cross_fibre_[a] + cross_fibre_[b]));
  }
  mesh_.normalize_membership();
  return std::move(mesh_);
}

}  // namespace systole::mesh::procedural
