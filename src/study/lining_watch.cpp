#include "study/lining_watch.h"

#include <map>

#include "mesh/anatomy.h"
#include "mesh/winding.h"

namespace systole::study {

LiningWatch::LiningWatch(const mesh::OrganMesh& mesh)
    : epicardium_(mesh::epicardium(mesh.anatomy)), lining_(mesh::lining_vertices(mesh.anatomy)) {
  std::map<int, std::string> cavity;
  for (const mesh::Cavity& c : mesh.anatomy.cavities) {
    for (const Eigen::Vector3i& t : c.lining) {
      for (int k = 0; k < 3; ++k) cavity.emplace(t[k], c.name);
    }
  }
  for (int v : lining_) cavity_of_.push_back(cavity[v]);
  points_.resize(3, static_cast<Eigen::Index>(lining_.size()));
}

int LiningWatch::check(const Eigen::Matrix3Xd& positions, int frame) {
  if (empty()) return 0;
  for (std::size_t i = 0; i < lining_.size(); ++i) points_.col(static_cast<Eigen::Index>(i)) = positions.col(lining_[i]);
  const std::vector<int> winding = mesh::winding_numbers(positions, epicardium_, points_);
  int outside = 0, first = -1;
  for (std::size_t i = 0; i < winding.size(); ++i) {
    if (winding[i] > 0) continue;
    if (first < 0) first = static_cast<int>(i);
    ++outside;
  }
  ++frames_;
  if (outside > 0) ++frames_outside_;
  if (outside > worst_outside_) {
    worst_outside_ = outside;
    worst_frame_ = frame;
    worst_vertex_ = lining_[static_cast<std::size_t>(first)];
    worst_cavity_ = cavity_of_[static_cast<std::size_t>(first)];
  }
  return outside;
}

}  // namespace systole::study
