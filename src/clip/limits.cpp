#include "clip/limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/error.h"
#include "mesh/file_bounds.h"

namespace systole::clip {
namespace {

// Compressed bytes per pixel of a frame as the shipped scenes give them (docs/robustness.md):
// H.264 at crf 20, 0.0055 (heart, 320x240, 1 s); PNG, 0.16 (the gallery stills, 640x360).
// Times 4 for busier frames than one organ on a plain background.
constexpr double kVideoBytesPerPixel = 4 * 0.006;
constexpr double kPngBytesPerPixel = 4 * 0.16;

[[noreturn]] void over(const scene::Scene& scene, const std::string& what, const std::string& limit) {
  throw Error(ExitCode::kDataError, scene.path + ": " + what + " is over the limit of " + limit +
                                        " (docs/robustness.md); pass --allow-large to do it anyway");
}

std::string count(std::int64_t n) {
  std::ostringstream s;
  s << n;
  return s.str();
}

std::string megabytes(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / (1 << 20) << " MiB";
  return s.str();
}

}  // namespace

Limits Limits::none() {
  constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
  return {kMax, std::numeric_limits<double>::infinity(), kMax, kMax, kMax};
}

void apply_to_mesh_reader(const Limits& limits) {
  mesh::ImportLimits& reader = mesh::import_limits();
  if (limits.max_vertices == std::numeric_limits<std::int64_t>::max()) {
    reader = mesh::ImportLimits::none();
  } else {
    reader = mesh::ImportLimits{};
    reader.max_vertices = limits.max_vertices;
  }
}

std::int64_t estimated_output_bytes(const scene::Scene& scene, const PlannedOutput& planned) {
  const double pixels = static_cast<double>(scene.output.width) * scene.output.height * planned.frames;
  const double bytes = pixels * ((planned.video ? kVideoBytesPerPixel : 0) + (planned.png ? kPngBytesPerPixel : 0));
  return static_cast<std::int64_t>(std::ceil(bytes));
}

void check_scene_limits(const scene::Scene& scene, const PlannedOutput& planned, const Limits& limits) {
  const auto& out = scene.output;
  const std::int64_t pixels = static_cast<std::int64_t>(out.width) * out.height;
  if (pixels > limits.max_frame_pixels) {
    over(scene, "output.width x output.height = " + std::to_string(out.width) + "x" + std::to_string(out.height) + " = " +
                    count(pixels) + " pixels",
         count(limits.max_frame_pixels) + " pixels (3840x2160)");
  }
  if (out.duration_s * std::max(1.0, out.slow_motion) > limits.max_duration_s) {
    std::ostringstream what, limit;
    what << "output.duration = " << out.duration_s << " s";
    if (out.slow_motion > 1) what << " at output.slow_motion " << out.slow_motion << " (" << out.duration_s * out.slow_motion << " s of video)";
    limit << limits.max_duration_s << " s";
    over(scene, what.str(), limit.str());
  }
  const std::int64_t bytes = estimated_output_bytes(scene, planned);
  if (bytes > limits.max_output_bytes) {
    over(scene, "the estimated output size, " + megabytes(static_cast<double>(bytes)) + " for " +
                    std::to_string(planned.frames) + " frames,",
         megabytes(static_cast<double>(limits.max_output_bytes)));
  }
}

void check_world_limits(const scene::Scene& scene, const world::World& world, const Limits& limits) {
  std::int64_t vertices = 0, substeps_per_frame = 0;
  for (const auto& body : world.organs) {
    vertices += static_cast<std::int64_t>(body.geometry.mesh.surface.positions.size());
    substeps_per_frame += static_cast<std::int64_t>(world.steps_per_frame) * body.model.substeps;
  }
  if (vertices > limits.max_vertices) {
    over(scene, "the organs' " + count(vertices) + " vertices", count(limits.max_vertices) + " vertices");
  }
  // In floating point: a tiny dt over a long clip overflows any integer.
  // A loop's settling frames are simulated too.
  const double substeps = static_cast<double>(substeps_per_frame) * (scene.output.start_frame + scene.output.frame_count());
  if (substeps > static_cast<double>(limits.max_substeps)) {
    std::ostringstream what;
    what << "the solver's " << substeps << " substeps over the clip (" << world.steps_per_frame
         << " steps per frame of solver.dt " << world.dt_s << " s, times solver.substeps)";
    over(scene, what.str(), count(limits.max_substeps) + " substeps");
  }
}

}  // namespace systole::clip
