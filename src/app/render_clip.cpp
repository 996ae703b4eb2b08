#include "app/render_clip.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <numeric>
#include <vector>

#include "app/bake.h"
#include "app/frame_list.h"
#include "app/frame_pipeline.h"
#include "app/overlay_plan.h"
#include "app/progress.h"
#include "app/world.h"
#include "common/error.h"
#include "encode/mp4_writer.h"
#include "encode/png.h"
#include "mesh/normals.h"
#include "render/fxaa.h"
#include "render/renderer.h"

namespace systole::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::vector<scene::Color> vertex_colors(const scene::Organ& organ, const std::vector<int>& vertex_region) {
  std::vector<scene::Color> colors(vertex_region.size(), organ.material.color);
  for (std::size_t i = 0; i < vertex_region.size(); ++i) {
    const int r = vertex_region[i];
    if (r >= 0 && organ.regions[r].has_color) colors[i] = organ.regions[r].color;
  }
  return colors;
}

/// One organ's surface for one frame, as the renderer takes it (allocated once per slot).
struct SurfaceBuffers {
  Eigen::Matrix3Xd mesh_positions;  ///< The render mesh's vertices this frame (render_positions). unit: m
  std::vector<float> positions, normals;  ///< xyz per vertex. unit: m, 1
};

/// Frames in flight between two stages. Three: one being written, one being read, and one
/// ready, so a stage that is briefly slower does not stall the other.
constexpr int kPipelineDepth = 3;

/// Threads the stages get, for the two-core machines we target (docs/performance.md):
/// llvmpipe rasterizes on one thread of its own while the simulation and the encoder run
/// beside it; more threads only contend for the same two cores.
constexpr const char* kRasterizerThreads = "1";
constexpr int kEncoderThreads = 1;

/// The frames to render: the request's list checked against the clip, or every frame.
std::vector<int> selected_frames(const RenderRequest& request, int frame_count) {
  if (request.frames.empty()) {
    std::vector<int> all(frame_count);
    std::iota(all.begin(), all.end(), 0);
    return all;
  }
  for (std::size_t i = 0; i < request.frames.size(); ++i) {
    const int f = request.frames[i];
    if (f < 0 || f >= frame_count) {
      throw Error(ExitCode::kUsage, "frame " + std::to_string(f) + " is outside the clip: it has " +
                                        std::to_string(frame_count) + " frames (0.." +
                                        std::to_string(frame_count - 1) + ")");
    }
    if (i > 0 && f <= request.frames[i - 1]) {
      throw Error(ExitCode::kUsage, "the frame list must be sorted and without duplicates");
    }
  }
  if (!request.video.empty() && !is_contiguous(request.frames)) {
    throw Error(ExitCode::kUsage,
                "a video needs consecutive frames (a range such as 10..20); write other selections as PNG frames");
  }
  return request.frames;
}

}  // namespace

std::filesystem::path default_video_path(const scene::Scene& scene) {
  if (!scene.output.file.empty()) return scene.output.file;
  return std::filesystem::path("out") / (scene.name + ".mp4");
}

StageTimes render_clip(const scene::Scene& scene, const RenderRequest& request) {
  const auto start = Clock::now();
  StageTimes times;
  const auto& out = scene.output;
  const int frame_count = out.frame_count();
  const std::vector<int> frames = selected_frames(request, frame_count);
  check_scene_limits(scene, {static_cast<int>(frames.size()), !request.video.empty(), !request.png_dir.empty()},
                     request.limits);
  World world = build_world(scene);
  check_world_limits(scene, world, request.limits);
  // Read when the process creates its first context; a value set by the caller wins.
  setenv("LP_NUM_THREADS", kRasterizerThreads, /*overwrite=*/0);
  const int msaa = out.antialias == scene::Antialias::kMsaa4 ? 4 : out.antialias == scene::Antialias::kMsaa2 ? 2 : 0;
  render::Renderer renderer(out.width, out.height, msaa);

  // slots[k][o]: organ o of the frame in slot k.
  std::vector<std::vector<SurfaceBuffers>> slots(kPipelineDepth, std::vector<SurfaceBuffers>(world.organs.size()));
  std::vector<int> surface_ids;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& body = world.organs[o];
    const auto& organ = scene.organs[o];
    surface_ids.push_back(renderer.add_surface(body.geometry.mesh.surface.triangles,
                                               vertex_colors(organ, body.geometry.vertex_region), organ.material));
    for (auto& slot : slots) {
      slot[o].positions.resize(3 * body.geometry.mesh.surface.positions.size());
      slot[o].normals.resize(3 * body.geometry.mesh.surface.positions.size());
    }
  }

  // Sinks are opened before the first frame so a bad output path fails before any work.
  std::vector<std::unique_ptr<encode::FrameSink>> sinks;
  if (!request.video.empty()) {
    encode::VideoSettings video{out.width, out.height, out.fps, out.crf, out.preset, kEncoderThreads};
    sinks.push_back(std::make_unique<encode::Mp4Writer>(request.video, video));
  }
  if (!request.png_dir.empty()) {
    sinks.push_back(std::make_unique<encode::PngSequenceWriter>(request.png_dir, frame_count));
  }

  // Overlays: anchors captured with the positions (produce), handed on through the render
  // stage's slots (produce may refill its slot before consume is done), drawn after FXAA.
  OverlayPlan overlay(scene, world);
  std::vector<OverlayFrame> overlay_produced(kPipelineDepth), overlay_rendered(kPipelineDepth);
  Eigen::Matrix3Xd volume_positions;
  if (!overlay.volume_organs().empty() && request.from_bake.empty()) {
    const auto record = [&](int frame) {
      for (int o : overlay.volume_organs()) {
        render_positions(world.organs[static_cast<std::size_t>(o)], volume_positions);
        overlay.record_volume(o, frame, volume_positions);
      }
    };
    if (world.frames_done == 0) record(0);
    world.after_frame = record;
  }
  std::vector<const Eigen::Matrix3Xd*> frame_positions(world.organs.size());

  std::vector<Image> images(kPipelineDepth, Image(out.width, out.height));
  render::Fxaa fxaa;
  std::optional<BakeReader> bake;
  if (!request.from_bake.empty()) bake.emplace(request.from_bake).check_matches(scene, world);
  Progress progress(request.job.empty() ? scene.name : request.job, static_cast<int>(frames.size()),
                    request.progress);

  // Each stage adds to its own times only (one thread each).
  PipelineStages stages;
  stages.produce = [&](int i, int slot) {
    const int f = frames[static_cast<std::size_t>(i)];
    auto t0 = Clock::now();
    if (!bake) advance_to_frame(world, f);  // Steps through every frame in between.
    for (std::size_t o = 0; o < world.organs.size(); ++o) {
      auto& buf = slots[static_cast<std::size_t>(slot)][o];
      // The positions source: the simulation, or a bake of it.
      if (bake) {
        bake->read(f, static_cast<int>(o), buf.mesh_positions);
      } else {
        render_positions(world.organs[o], buf.mesh_positions);
      }
      const Eigen::Index n = buf.mesh_positions.cols();
      const double* x = buf.mesh_positions.data();
      for (Eigen::Index k = 0; k < 3 * n; ++k) buf.positions[k] = static_cast<float>(x[k]);
      mesh::vertex_normals(x, static_cast<int>(n), world.organs[o].geometry.mesh.surface.triangles,
                           buf.normals.data());
      frame_positions[o] = &buf.mesh_positions;
    }
    times.simulate_s += seconds_since(t0);
    if (!overlay.empty()) {
      t0 = Clock::now();
      // From a bake, the volume history comes from the bake's frames (every one up to this).
      for (int o : bake ? overlay.volume_organs() : std::vector<int>{}) {
        for (int g = 0; g <= f; ++g) {
          if (overlay.has_volume(o, g)) continue;
          bake->read(g, o, volume_positions);
          overlay.record_volume(o, g, volume_positions);
        }
      }
      overlay.capture(f, frame_positions, overlay_produced[static_cast<std::size_t>(slot)]);
      times.simulate_s += seconds_since(t0);  // This thread's own sum: the capture is counted with it.
    }
  };
  stages.render = [&](int, int slot) {
    auto t0 = Clock::now();
    for (std::size_t o = 0; o < surface_ids.size(); ++o) {
      const auto& buf = slots[static_cast<std::size_t>(slot)][o];
      renderer.update_surface(surface_ids[o], buf.positions.data(), buf.normals.data());
    }
    renderer.draw(scene.camera, scene.lights, out.background);
    times.render_s += seconds_since(t0);
    t0 = Clock::now();
    renderer.read_frame(images[static_cast<std::size_t>(slot)]);
    times.readback_s += seconds_since(t0);
    if (!overlay.empty()) overlay_rendered[static_cast<std::size_t>(slot)] = overlay_produced[static_cast<std::size_t>(slot)];
  };
  stages.consume = [&](int i, int slot) {
    Image& image = images[static_cast<std::size_t>(slot)];
    auto t0 = Clock::now();
    if (out.antialias == scene::Antialias::kFxaa) fxaa.apply(image);
    times.antialias_s += seconds_since(t0);
    if (!overlay.empty()) {
      // After FXAA: text and lines stay crisp.
      t0 = Clock::now();
      overlay.draw(image, overlay_rendered[static_cast<std::size_t>(slot)]);
      times.overlay_s += seconds_since(t0);
    }
    t0 = Clock::now();
    for (auto& sink : sinks) sink->write(image, frames[static_cast<std::size_t>(i)]);
    times.encode_s += seconds_since(t0);
    ++times.frames;
    progress.update(times.frames);
  };
  run_frame_pipeline(static_cast<int>(frames.size()), kPipelineDepth, request.overlap, stages);

  const auto t0 = Clock::now();
  for (auto& sink : sinks) sink->finish();
  times.encode_s += seconds_since(t0);
  progress.finish();
  times.wall_s = seconds_since(start);
  return times;
}

std::string describe(const StageTimes& t) {
  const double n = t.frames > 0 ? t.frames : 1;
  char overlay[64] = "";
  if (t.overlay_s > 0) std::snprintf(overlay, sizeof overlay, ", overlay %.2f ms/frame", 1e3 * t.overlay_s / n);
  char text[512];
  std::snprintf(text, sizeof text,
                "%d frames in %.2f s: simulate %.2f ms/frame, render %.2f ms/frame, read back %.2f ms/frame, "
                "anti-alias %.2f ms/frame%s, encode %.2f ms/frame (stages overlapped)",
                t.frames, t.wall_s, 1e3 * t.simulate_s / n, 1e3 * t.render_s / n, 1e3 * t.readback_s / n,
                1e3 * t.antialias_s / n, overlay, 1e3 * t.encode_s / n);
  return text;
}

}  // namespace systole::app
