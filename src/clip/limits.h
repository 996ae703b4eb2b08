#pragma once
// Resource limits: a scene cannot ask for absurd work by accident. Every limit is checked
// before the work it bounds starts; `systole render --allow-large` lifts them on purpose.
// docs/robustness.md lists them and why each is where it is.

#include <cstdint>

#include "scene/scene.h"
#include "world/world.h"

namespace systole::clip {

struct Limits {
  std::int64_t max_frame_pixels = 3840LL * 2160;  ///< width x height: 4K UHD. unit: px
  double max_duration_s = 600;                     ///< Length of the clip. unit: s
  std::int64_t max_vertices = 2'000'000;           ///< Over all organs, after welding.
  std::int64_t max_substeps = 20'000'000;          ///< Solver substeps over the clip, all organs.
  std::int64_t max_output_bytes = 8LL << 30;       ///< Estimated size of everything written. unit: byte

  /// No limit at all (--allow-large).
  static Limits none();
};

/// What a run will write, for the output size estimate.
struct PlannedOutput {
  int frames = 0;      ///< Frames rendered.
  bool video = false;  ///< An MP4.
  bool png = false;    ///< One PNG per frame.
};

/// Estimated bytes written: from the H.264 and PNG sizes of the shipped scenes per pixel
/// (docs/robustness.md), with a safety factor, since a busier frame compresses less.
std::int64_t estimated_output_bytes(const scene::Scene& scene, const PlannedOutput& planned);

/// Checked before anything is built: frame size, duration and estimated output size.
/// Throws Error(kDataError) naming the scene, the key, the value and the limit, and how
/// to lift it.
void check_scene_limits(const scene::Scene& scene, const PlannedOutput& planned, const Limits& limits);

/// Gives the mesh reader (mesh/file_bounds.h) these limits: a file holding more vertices
/// than the world may have is refused before it is read; Limits::none() lifts the reader's
/// limits too. Process-wide: the reader runs deep inside building the world.
void apply_to_mesh_reader(const Limits& limits);

/// Checked after the model is built and before the first step: vertex count and solver
/// substeps over the clip. Throws Error(kDataError) like check_scene_limits.
void check_world_limits(const scene::Scene& scene, const world::World& world, const Limits& limits);

}  // namespace systole::clip
