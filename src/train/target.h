#pragma once
// The motion an organ is trained to make: every particle's target position over one
// cycle, from key-frame meshes or per-region size curves, interpolated smoothly and
// periodically (a periodic Catmull-Rom spline through the key poses).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/organ.h"
#include "scene/scene.h"

namespace systole::train {

class TargetMotion {
 public:
  /// Key poses (3 x particles, world space) at increasing phases in [0, 1) of the cycle.
  TargetMotion(std::vector<double> phases, std::vector<Eigen::Matrix3Xd> poses);

  /// Every particle's target at phase u (cycles; any real, taken modulo 1). unit: m
  void positions(double u, Eigen::Matrix3Xd& out) const;
  /// The surface vertices it moves (the organ's render surface).
  int particle_count() const { return static_cast<int>(poses_.front().cols()); }

  /// How a target of another mesh was laid on the organ and what the transfer loses
  /// (train/transfer.h); "" for a target of the organ's own mesh or curves.
  const std::string& transfer_note() const { return transfer_note_; }
  void set_transfer_note(std::string note) { transfer_note_ = std::move(note); }

 private:
  std::vector<double> phases_;
  std::vector<Eigen::Matrix3Xd> poses_;
  std::string transfer_note_;
};

/// The organ's target in world space, on its render surface. An animation file (any mesh:
/// glTF/GLB and what assimp reads, for now) is aligned to the organ and transferred onto its
/// surface (train/transfer.h). Key-frame files are read with assimp like the organ's
/// own mesh file (same units, same centring offset, same transform: a frame's displacement
/// from the organ's undeformed mesh is placed like the mesh); a procedural organ's frames are
/// in its generator's frame, metres. Curves scale each region about its rest centroid (a
/// volume v as scale v^(1/3)); particles in no curve's region stay at rest.
/// Throws Error(kDataError) naming the file when a frame's vertex count differs.
TargetMotion load_target(const scene::Organ& organ, const mesh::OrganGeometry& geometry);

}  // namespace systole::train
