#pragma once
// glTF/GLB morph-target animation read by hand over nlohmann/json, not by assimp: assimp
// 5.2 drops negative morph weights to 0 (the kidney's exported first key [-0.010, -0.004,
// 0.002, 0] came out as [0, 0, 0.0018, 0.0001]), and every animation `systole export`
// writes weighs its principal modes both ways, as many shape-key exports do. (tinygltf, which
// writes our glTF, cannot read it here: Debian's libdraco, linked through assimp, carries
// another build of it whose loader wins at run time.) A file whose first animation moves only
// morph weights is read here, every primitive of a mesh sharing its vertices once; one whose
// animation moves nodes (skinning) is left to mesh/animation.h.

#include <filesystem>
#include <optional>

#include "mesh/animated_surface.h"

namespace systole::mesh {

/// The first animation of a .gltf/.glb file, when it animates morph weights only: vertices
/// placed by their nodes' (static) transforms, each mesh a part (its name, else its node's),
/// and `samples` poses evenly over period `period` of the `cycles` it holds (0: at its own keys
/// where they are evenly spaced, else kDefaultSamples), a pose being
/// rest + sum of weight x displacement (weights interpolated as the sampler says: linear,
/// step, or a cubic spline's values). nullopt when the animation moves nodes or the file has
/// no morph targets. Throws Error(kDataError) naming the file when it cannot be read, has no
/// animation, or an accessor is out of bounds.
std::optional<AnimatedSurface> read_gltf_morphs(const std::filesystem::path& file, int samples, int cycles, int period);

}  // namespace systole::mesh
