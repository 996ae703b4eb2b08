#pragma once
// Per-vertex strain of a surface: for each vertex, the mean over its edges of the relative
// length change (L - L0) / L0 against the rest shape. The edges are the surface's unique
// triangle edges - the springs of the full mass-spring model - so a contracting region
// reads negative (shortened) and a stretched one positive, whatever model moved the mesh.

#include <Eigen/Core>
#include <vector>

namespace systole::mesh {

class VertexStrain {
 public:
  /// Unique edges of `triangles` and their rest lengths from `rest_positions` (unit: m).
  /// A zero-length rest edge is skipped (its strain is undefined).
  VertexStrain(const std::vector<Eigen::Vector3d>& rest_positions, const std::vector<Eigen::Vector3i>& triangles);

  /// Strain of every vertex at `positions` (3 x n, unit: m) into `out` (size n, unit: 1);
  /// a vertex without edges gets 0. Fixed summation order: the same bits on every run.
  void compute(const Eigen::Matrix3Xd& positions, std::vector<double>& out) const;

  int vertex_count() const { return vertex_count_; }

 private:
  int vertex_count_ = 0;
  std::vector<Eigen::Vector2i> edges_;  ///< Vertex pairs, a < b, sorted.
  std::vector<double> rest_m_;          ///< Rest length per edge. unit: m
  std::vector<int> degree_;             ///< Edges per vertex.
};

}  // namespace systole::mesh
