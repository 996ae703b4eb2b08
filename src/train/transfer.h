#pragma once
// A target of any mesh laid on the organ (issue 37): an animation from an artist, from
// Blender, from a point cache or from `systole export` at another detail is never the
// organ's own mesh, vertex for vertex. Two steps:
// - Alignment: the target's rest surface is placed on the organ's rest surface: as its file
//   is placed (the organ's units and transform), as it is (already in the scene's frame), or,
//   when neither fits, by iterative closest points with a rigid motion plus a uniform scale
//   (an affine map on request), from landmark pairs when the scene gives them. A target that
//   no alignment brings within kMaxMisfit of the organ is refused.
// - Binding: every organ surface vertex takes the nearest point of the aligned target's
//   surface (on the same named part where both have one), as that triangle's barycentric
//   point plus an offset in the triangle's own frame, so it follows the triangle as the
//   target deforms. A target of the organ's own mesh binds each vertex to its counterpart
//   exactly.
// What the transfer loses is measured the other way: the target's vertices bound to the
// organ's surface, replayed from the transferred motion, against the target's own motion.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "mesh/animated_surface.h"

namespace systole::train {

/// How far apart two surfaces may lie after alignment and still be called the same organ:
/// the RMS of both ways' distances to the other surface, as a share of the organ's bounding diagonal.
inline constexpr double kMaxMisfit = 0.05;

/// A target within this of the organ as its file is placed (or as it is) is kept there, not
/// aligned further: its rest shape may differ from the organ's for real. A share of the
/// organ's bounding diagonal.
inline constexpr double kPlacedClose = 0.005;

/// Farther than kPlacedClose, a target is still kept where its file puts it unless aligning
/// it brings it more than this many times closer: moving explains little of its misfit, the
/// rest is shape (a clip's mean pose is not the organ's rest).
inline constexpr double kKeptUnlessMovedCloser = 2.0;

/// A surface at rest: vertices (3 x n) and triangles, with optional part names per vertex.
struct RestSurface {
  Eigen::Matrix3Xd positions;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<std::string> vertex_part_name;  ///< Per vertex, its part's name ("" none); empty: no parts.
};

struct AlignOptions {
  enum class Mode { kSimilarity, kAffine };
  Mode mode = Mode::kSimilarity;
  /// Pairs (point on the target, point on the organ), both in their own frames; 3 or more
  /// start the alignment, fewer are not used.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> landmarks;
  /// The organ's placement of a file in its mesh's units and frame: organ = linear * file + offset.
  Eigen::Matrix3d placed_linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d placed_offset = Eigen::Vector3d::Zero();
};

/// organ point = linear * target point + offset.
struct Alignment {
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  double misfit = 0;        ///< RMS distance to the other surface both ways, share of the organ's diagonal. unit: 1
  double scale_vs_placed = 1;  ///< The alignment's size against the file's placement (1: the units agree). unit: 1
  std::string how;          ///< "as placed", "as it is", "landmarks + closest points (similarity)", ...

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return linear * p + offset; }
};

/// Aligns `target` to `organ` (header). Throws Error(kDataError) naming `what` (the target's
/// file and the organ) when the best alignment's misfit exceeds kMaxMisfit, or when its size
/// is over twice or under half the placement's (the file's units are then not the organ's).
Alignment align(const RestSurface& target, const RestSurface& organ, const AlignOptions& options, const std::string& what);

/// Organ vertices bound to a target surface (header).
class SurfaceBinding {
 public:
  /// Binds every vertex of `to` to the nearest point of `from`'s surface (both at rest, in
  /// the same frame), on the part of the same name where `from` has it (a name matches when
  /// equal, or when one is the other's last segment after '/').
  SurfaceBinding(const RestSurface& from, const RestSurface& to);
  /// `to`'s vertices for `from` posed at `from_pose` (3 x from's vertices). unit: m
  void apply(const Eigen::Matrix3Xd& from_pose, Eigen::Matrix3Xd& out) const;
  /// The largest distance of a bound vertex from its point at rest. unit: as the positions
  double largest_gap() const { return largest_gap_; }

 private:
  std::vector<Eigen::Vector3i> corners_;  ///< The bound triangle's corners, per vertex.
  std::vector<Eigen::Vector3d> bary_, offset_;  ///< Barycentric weights; offset in the triangle's frame.
  double largest_gap_ = 0;
};

/// What the transfer loses: `target`'s vertices bound to the organ's rest surface, replayed
/// from the transferred poses `organ_poses`, against `target_poses` (both aligned, same
/// count): the RMS displacement error over vertices and poses, as a share of the target's
/// RMS motion about its mean shape. unit: %
double transfer_loss_pct(const RestSurface& target, const std::vector<Eigen::Matrix3Xd>& target_poses,
                         const RestSurface& organ, const std::vector<Eigen::Matrix3Xd>& organ_poses);

}  // namespace systole::train
