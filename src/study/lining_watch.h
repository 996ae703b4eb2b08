#pragma once
// Whether a generated anatomy's linings stay inside its walls as it moves. Its parts are
// labels on one welded wall, so they are not watched for passing through each other
// (study/part_crossing.h); what can go wrong is the wall itself: a cavity's lining crossing
// its wall's outside, where a view from outside then sees the lining (docs/anatomy.md,
// "The wall keeps its lining inside"). At each check every lining vertex that is not also on
// the outside (mesh::lining_vertices) is tested against the walls' closed outside (the
// epicardium) by its winding number (mesh/winding.h).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace systole::study {

class LiningWatch {
 public:
  /// Watches `mesh`'s anatomy; a mesh without one has nothing to watch (empty()).
  explicit LiningWatch(const mesh::OrganMesh& mesh);

  bool empty() const { return lining_.empty(); }
  /// The lining vertices watched.
  int lining_vertices() const { return static_cast<int>(lining_.size()); }

  /// Looks at the surface at `positions` (the mesh's vertices, moved), frame `frame`; returns
  /// how many lining vertices lie outside the epicardium.
  int check(const Eigen::Matrix3Xd& positions, int frame);

  int frames() const { return frames_; }  ///< Checks made.
  int frames_outside() const { return frames_outside_; }  ///< Checks that found a lining vertex outside.
  int worst_outside() const { return worst_outside_; }  ///< The most outside at one check.
  int worst_frame() const { return worst_frame_; }  ///< Its frame; -1: none outside.
  /// A lining vertex outside at the worst check and the cavity it lines ("" if none).
  int worst_vertex() const { return worst_vertex_; }
  const std::string& worst_cavity() const { return worst_cavity_; }

 private:
  std::vector<Eigen::Vector3i> epicardium_;
  std::vector<int> lining_;
  std::vector<std::string> cavity_of_;  ///< Per watched vertex: the cavity it lines.
  Eigen::Matrix3Xd points_;             ///< Scratch: the lining vertices' positions.
  int frames_ = 0, frames_outside_ = 0, worst_outside_ = 0, worst_frame_ = -1, worst_vertex_ = -1;
  std::string worst_cavity_;
};

}  // namespace systole::study
