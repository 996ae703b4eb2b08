#pragma once
// An organ's motion as morph targets and weight curves, the way glTF animates a deforming
// mesh: position(t) = base + sum_k w_k(t) delta_k, normals the same way.
//
// Two encodings. `frames`: every frame is a target (delta = frame - rest), its weight 1 at
// its own key and 0 elsewhere, so a viewer reproduces each simulated frame to float32
// rounding; size grows with the clip. `compact`: the rest as base (a shape key's basis), the
// mean shape over whole cycles as a target held at 1, and the displacement from the mean
// compressed into its principal components (PCA of the frames by the
// snapshot method: eigenvectors of the frames' Gram matrix, Sirovich 1987), the fewest
// targets from min_targets to max_targets whose float32 reconstruction is within the error
// budget, measured as sim/motion_error.h measures error: RMS distance as a share of the RMS
// motion. Its weight curves close the loop: the key after the last frame repeats the first.
//
// Inputs:  a Recording's organ (export/recording.h).
// Outputs: a MorphAnimation (float32, what the file stores).
// See also: export/gltf.h, docs/export.md.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "export/recording.h"

namespace systole::exporter {

enum class Encoding { kFrames, kCompact };

struct MorphAnimation {
  Eigen::Matrix3Xf base_position_m;  ///< The mesh without morphing: the organ's rest. unit: m
  Eigen::Matrix3Xf base_normal;      ///< Unit vertex normals of the base. unit: 1
  std::vector<Eigen::Matrix3Xf> position_delta_m;  ///< Per target. unit: m
  std::vector<Eigen::Matrix3Xf> normal_delta;      ///< Per target. unit: 1
  std::vector<std::string> target_names;
  std::vector<float> key_times_s;    ///< Video time of each key, from 0. unit: s
  Eigen::MatrixXf weights;           ///< keys x targets. unit: 1
  double error_pct = 0;              ///< RMS error of the keys' shapes against the simulated frames, share of the motion. unit: %
  double motion_m = 0;               ///< RMS motion of the frames (sim::rms_motion_m). unit: m

  int target_count() const { return static_cast<int>(position_delta_m.size()); }
};

struct CompactOptions {
  double max_error_pct = 2;  ///< unit: % of the motion (RMS)
  int min_targets = 4;   ///< Principal components; the mean shape's target comes on top.
  int max_targets = 16;
};

/// Every frame a target. A loop gets a closing key (frame 0 again) one frame after the last.
MorphAnimation frames_morph(const OrganTrack& organ, const Recording& rec);

/// The compact loop. Throws Error(kUsage) unless the recording is a loop, and
/// Error(kDataError) when max_targets components miss the budget (naming the error reached).
MorphAnimation compact_morph(const OrganTrack& organ, const Recording& rec, const CompactOptions& options);

/// Unit vertex normals of the surface at `positions_m` (mesh::vertex_normals). unit: 1
Eigen::Matrix3Xf vertex_normals(const OrganTrack& organ, const Eigen::Matrix3Xd& positions_m);

/// The positions the animation gives at key k, as a viewer computes them (from the stored
/// float32 values). unit: m
Eigen::Matrix3Xd shape_at_key(const MorphAnimation& morph, int key);

}  // namespace systole::exporter
