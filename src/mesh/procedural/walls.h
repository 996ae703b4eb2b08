#pragma once
// Thick muscular walls for the anatomical heart: each chamber pair (ventricle below, atrium
// above) is a wall of revolution about its own long axis, given by its lining's meridian
// (from the apex round to the top of the atrium) and the wall's thickness along it; a
// vessel is a straight hollow tube. Each wall is a hexahedral lattice laid along it
// (around, along and across, so a 4-mm wall has three cells across it at any size), with the
// muscle fibre direction at every point, and its two surfaces sampled finer for drawing, every
// drawn vertex following the lattice cell it lies in.

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mesh/anatomy.h"
#include "mesh/mesh.h"

namespace systole::mesh::procedural {

using Vec = Eigen::Vector3d;

/// Where a point lies in a wall: angle around the axis, fraction along the meridian (0 at the
/// apex, 1 at the far pole or end), fraction across the wall (0 lining, 1 outside).
struct WallPoint {
  double around = 0;  ///< unit: rad, [0, 2 pi)
  double along = 0;   ///< unit: 1
  double across = 0;  ///< unit: 1
};

struct WallShape {
  Vec origin, axis, e1, e2;  ///< Axis: towards the apex; around = 0 along e1. unit: m
  /// The lining's meridian from pole to pole (radius 0 at both ends) or along a tube:
  /// height along the axis, radius from it, wall thickness; a smooth curve passes through them.
  std::vector<double> height, radius, thickness;  ///< unit: m
  bool tube = false;  ///< Open at both ends (a vessel) instead of closed at the poles.
  /// Adjusts the lining's radius at (around, along): the nominal radius and thickness in,
  /// the radius out (bulges, and where the wall meets a neighbour's).
  std::function<double(double around, double along, double radius, double thickness)> shape_radius;
  /// Moves the ring at `along` off the axis (a bent axis: a chamber leaning towards its
  /// neighbour's apex); empty: straight. The wall's frame follows the bend. unit: m
  std::function<Vec(double along)> shift;
  /// Muscle fibre helix angle from the circumferential direction at a place across and along
  /// the wall (Streeter); empty: passive tissue (no fibres, contracts evenly if driven).
  std::function<double(double across, double along)> helix_rad;
  /// Cross-fibre shortening as a share of the fibre's, at a place across and along the wall.
  std::function<double(double across, double along)> cross_fibre;
  int columns = 16;        ///< Lattice nodes around.
  int rows_per_key = 1;    ///< Lattice rows per meridian key interval.
  int layers = 3;          ///< Lattice cells across the wall.
  int draw_columns = 48;   ///< Drawn vertices around.
  int draw_rows_per_key = 3;
};

/// What a drawn vertex (drawn: true) or lattice node belongs to: its first part and any others.
using PartsAt = std::function<std::vector<int>(const WallPoint&, bool drawn)>;

class HeartBuilder;

/// One wall built into the builder; remembers its numbering for landmarks and valves.
class Wall {
 public:
  Wall(HeartBuilder& builder, WallShape shape, const PartsAt& parts);

  /// The point at a place in the wall at rest. unit: m
  Vec point(const WallPoint& p) const;
  /// The wall's frame there: circumferential, along the meridian, outward normal.
  void frame(const WallPoint& p, Vec& circumferential, Vec& meridian, Vec& normal) const;
  /// The drawn vertex of the lining (across 0) or outside (across 1) at draw row r, column c.
  int drawn(int across, int row, int column) const;
  int draw_rows() const { return draw_rows_; }           ///< Rows including poles (or both tube ends).
  int draw_columns() const { return shape_.draw_columns; }
  double draw_along(int row) const { return double(row) / (draw_rows_ - 1); }
  /// The draw row at meridian key k.
  int draw_row_of_key(int k) const { return k * shape_.draw_rows_per_key; }
  /// Lattice nodes and weights that carry a point of the wall (up to 8).
  void carriers(const WallPoint& p, std::array<int, 8>& nodes, std::array<double, 8>& weights) const;
  /// This wall's lattice nodes within `reach` of x, nearest first, on the outside only or
  /// all (for gluing walls). unit: m
  std::vector<int> nodes_near(const Vec& x, double reach, int at_most, bool outside_only) const;
  /// Every lattice node on the outside, and every lattice node.
  std::vector<int> outside_nodes() const;
  /// The lining's triangles of draw rows [from, to) (a cavity's lining).
  std::vector<Eigen::Vector3i> lining(int from_row, int to_row) const;
  /// Every triangle of the wall's surfaces, facing out of it.
  const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }
  /// The lining radius after shape_radius at (around, along). unit: m
  double lining_radius(double around, double along) const;
  const WallShape& shape() const { return shape_; }
  /// Outer radius of the wall (from its axis) in the plane at `height` on the axis, or 0
  /// where the wall does not reach that plane, along the meridian at the first `around` asked
  /// (a wall of revolution: any will do where no bulge is). unit: m
  double outside_radius_at(double height, double around) const;

 private:
  /// The smooth curve through `keys` at `along`; `odd`: mirrored through zero at a pole (a
  /// radius), else evenly (a height, a thickness); a tube's ends continue straight.
  double key_value(const std::vector<double>& keys, double along, bool odd) const;
  double key_slope(const std::vector<double>& keys, double along, bool odd) const;
  void meridian(double along, double& height, double& radius, double& thickness, Eigen::Vector2d& normal) const;
  /// The outward normal at (around, along): the meridian's 2-D `normal` for a wall of
  /// revolution; where the axis bends or the lining's radius is shaped, the lining's own.
  Vec outward(double around, double along, const Eigen::Vector2d& normal) const;
  int node(int layer, int row, int column) const;  ///< row 0 and rows_ are the poles (closed walls).
  // The constructor's steps, in order: lattice nodes, cells, drawn vertices, triangles.
  void add_nodes(const PartsAt& parts);
  void add_cells();
  void add_drawn_vertices(const PartsAt& parts);
  void add_surfaces();

  HeartBuilder& builder_;
  WallShape shape_;
  int rows_ = 0;        ///< Lattice row intervals between the ends.
  int first_node_ = 0;
  int index_ = 0;  ///< This wall's number in the builder.
  int draw_rows_ = 0;
  std::vector<int> drawn_;  ///< [across][row][column] -> vertex.
  std::vector<std::vector<Eigen::Vector3i>> lining_band_;  ///< Per draw row interval.
  std::vector<Eigen::Vector3i> triangles_;
  mutable std::vector<std::pair<double, double>> outside_meridian_;  ///< (height, radius), sampled once.
};

/// Collects the walls, the drawn surfaces and the embedded parts of the heart.
class HeartBuilder {
 public:
  explicit HeartBuilder(std::vector<std::string> part_names);

  /// A lattice node of wall `wall` (numbered by begin_wall) at place `at` in it.
  int add_node(const Vec& x, const std::vector<int>& parts, const Vec& fibre, const Vec& normal, double cross_fibre,
               bool active, int wall, const WallPoint& at);
  /// The next wall's number (0, 1, ... in the order walls are built).
  int begin_wall() { return walls_++; }
  /// A cell's corners: its volume goes to them and every pair of them is a spring.
  void add_cell(const std::vector<int>& corners);
  /// A drawn vertex at x carried by `nodes`/`weights`, in `parts` (first part first).
  int add_vertex(const Vec& x, const std::vector<int>& parts, const std::array<int, 8>& nodes,
                 const std::array<double, 8>& weights);
  void add_triangle(int a, int b, int c) { mesh_.surface.triangles.emplace_back(a, b, c); }
  /// Adds triangle (a, b, c) turned to face `out`; returns it as added, or nothing if degenerate.
  std::optional<Eigen::Vector3i> add_triangle_facing(int a, int b, int c, const Vec& out);
  /// A passive spring holding two walls together where they touch.
  void glue(int a, int b) { glue_.emplace_back(a, b); }
  const Vec& node_position(int n) const { return mesh_.anatomy.myocardium.nodes[n]; }
  const Vec& vertex_position(int v) const { return mesh_.surface.positions[v]; }
  int part(const std::string& name) const;
  OrganMesh& mesh() { return mesh_; }

  /// Springs from the cells and glue, their weights and fibre shares; the finished mesh.
  OrganMesh finish();

 private:
  OrganMesh mesh_;
  std::vector<Vec> fibre_, normal_;
  std::vector<double> cross_fibre_;
  std::vector<char> active_;
  std::vector<std::vector<int>> cells_;
  std::vector<std::pair<int, int>> glue_;
  int walls_ = 0;
};

}  // namespace systole::mesh::procedural
