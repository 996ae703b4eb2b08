#pragma once
// Whether the parts of an organ's surface pass through each other as it moves. An atlas
// organ is many overlapping parts (chambers, valves, vessels); moved as one body they must
// keep the places they had at rest: a valve ring that lay on the outside of a chamber wall
// stays outside. This compares, for every vertex near another part, the side of that
// part's surface it is on with the side it was on at rest; a vertex on the other side has
// passed through, by its distance from the surface.
//
// Parts are the file's smallest named pieces: a group node or a material whose triangles
// include another part's is left out (its own pieces are checked), and names with the same
// triangles count once. A side is only taken where it is well defined: where the vertex's
// nearest point on the part lies inside a triangle (not on an edge or beyond an open
// part's border), both now and at rest. A vertex's rest side is looked up the first time it
// comes near a part.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/mesh.h"

namespace systole::study {

class PartCrossingWatch {
 public:
  /// Watches `mesh`'s parts as they move, the side of each vertex taken at the rest
  /// positions of `mesh`. A vertex is compared with the parts within `band_m` of it at each
  /// check: checked every frame, a vertex passing through a part is within the band on its
  /// far side for a frame as long as it moves less than the band a frame. unit: m
  PartCrossingWatch(const mesh::OrganMesh& mesh, double band_m);

  /// The parts checked against each other (fewer than two: nothing to check).
  const std::vector<std::string>& parts() const { return part_names_; }

  /// Looks at the surface at `positions` (the mesh's vertices, moved), frame `frame`.
  void check(const Eigen::Matrix3Xd& positions, int frame);

  struct Crossing {
    double depth_m = 0;  ///< How far past the other part's surface. unit: m
    int vertex = -1;
    std::string from, into;  ///< The vertex's part and the part it passed through.
    int frame = -1;
  };
  /// The deepest crossing seen (depth 0, vertex -1: none).
  const Crossing& worst() const { return worst_; }
  /// Vertex-part pairs that came within the band and whose sides were compared.
  std::size_t pairs_compared() const { return rest_side_.size(); }

 private:
  /// Triangles binned in a uniform grid of cubes, for the triangles near a point.
  struct Grid {
    double cell_m = 0;
    Eigen::Vector3d min = Eigen::Vector3d::Zero();
    Eigen::Vector3i size = Eigen::Vector3i::Zero();
    std::vector<int> start, triangles;  ///< Cell c holds triangles[start[c] .. start[c + 1]).
    std::vector<int> fill;              ///< Scratch of bin: the next free slot per cell.
  };
  /// Bins the triangles at positions `x` into `grid` (its storage reused: a check a frame).
  void bin(const Eigen::Matrix3Xd& x, double cell_m, Grid& grid) const;
  /// For each part other than the vertex's own with a point within `radius_m` of vertex v
  /// at `x` (only `part` when >= 0): found(part, side), the signed distance to the nearest
  /// such point, positive on the side its triangle faces, NaN where the point lies on an
  /// edge or a corner (no side there).
  template <class Found>
  void near_parts(const Grid& grid, const Eigen::Matrix3Xd& x, int v, double radius_m, int part, Found&& found) const;

  std::vector<std::string> part_names_;
  std::vector<Eigen::Vector3i> triangles_;  ///< Triangles of the checked parts.
  std::vector<int> triangle_part_;          ///< Per triangle: its part (index into part_names_).
  std::vector<std::vector<int>> vertex_parts_;  ///< Per vertex: the checked parts it belongs to.
  Eigen::Matrix3Xd rest_;
  Grid rest_grid_, grid_;  ///< At rest, and at the last check.
  double band_m_ = 0;
  std::unordered_map<std::uint64_t, double> rest_side_;  ///< (vertex, part) -> signed distance at rest.
  mutable std::vector<int> stamp_;
  mutable int stamp_now_ = 0;
  Crossing worst_;
};

}  // namespace systole::study
