#pragma once
// Animated mesh files through assimp: the poses of a file's first animation, by morph
// targets (blend shapes) and skinning (bones driven by animated nodes), e.g. a glTF/GLB
// exported from Blender or Maya. Used as a training target (train/target.cpp).

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "mesh/animated_surface.h"

namespace systole::mesh {

/// The first animation of `file` as a surface of its own (mesh/animated_surface.h): its
/// vertices as the file holds them (no welding: the animation moves them one by one, node
/// transforms applied), its triangles, each mesh a part (named as import_mesh names it), and
/// `samples` poses (0: kDefaultSamples) evenly spaced over one of the `cycles` periods the animation holds: period
/// `period` (0-based; the whole animation for 1 cycle). A vertex moves by its mesh's morph
/// targets (assimp keeps them as whole target shapes; the pose is rest + sum of weight x
/// (target - rest), weights interpolated linearly between keys) and, when the mesh has bones,
/// by linear blend skinning with the bone nodes' animated transforms (positions and scales
/// linear, rotations slerped). Throws Error(kNoInput) for a missing file, Error(kDataError)
/// naming the file when it has no animation.
AnimatedSurface read_animated_file(const std::filesystem::path& file, int samples, int cycles, int period);

}  // namespace systole::mesh
