#include "app/render_clip.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <numeric>
#include <vector>

#include "app/frame_list.h"
#include "app/progress.h"
#include "app/world.h"
#include "common/error.h"
#include "encode/mp4_writer.h"
#include "encode/png.h"
#include "mesh/normals.h"
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

/// Per-organ buffers handed to the renderer each frame (allocated once).
struct SurfaceBuffers {
  int id = 0;
  std::vector<float> positions, normals;
};

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
  World world = build_world(scene);
  render::Renderer renderer(out.width, out.height, out.antialias);

  std::vector<SurfaceBuffers> surfaces(world.organs.size());
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& body = world.organs[o];
    const auto& organ = scene.organs[o];
    surfaces[o].id = renderer.add_surface(body.geometry.mesh.surface.triangles,
                                          vertex_colors(organ, body.geometry.vertex_region), organ.material);
    surfaces[o].positions.resize(3 * body.model.particle_count());
    surfaces[o].normals.resize(3 * body.model.particle_count());
  }

  // Sinks are opened before the first frame so a bad output path fails before any work.
  std::vector<std::unique_ptr<encode::FrameSink>> sinks;
  if (!request.video.empty()) {
    encode::VideoSettings video{out.width, out.height, out.fps, out.crf, out.preset, 0};
    sinks.push_back(std::make_unique<encode::Mp4Writer>(request.video, video));
  }
  if (!request.png_dir.empty()) {
    sinks.push_back(std::make_unique<encode::PngSequenceWriter>(request.png_dir, frame_count));
  }

  Image frame(out.width, out.height);
  Progress progress(scene.name, static_cast<int>(frames.size()), request.show_progress);
  for (const int f : frames) {
    auto t0 = Clock::now();
    advance_to_frame(world, f);  // Steps through every frame in between.
    times.simulate_s += seconds_since(t0);

    t0 = Clock::now();
    for (std::size_t o = 0; o < world.organs.size(); ++o) {
      const auto& body = world.organs[o];
      auto& buf = surfaces[o];
      const Eigen::Index n = body.state.x.cols();
      const double* x = body.state.x.data();
      for (Eigen::Index i = 0; i < 3 * n; ++i) buf.positions[i] = static_cast<float>(x[i]);
      mesh::vertex_normals(x, static_cast<int>(n), body.geometry.mesh.surface.triangles, buf.normals.data());
      renderer.update_surface(buf.id, buf.positions.data(), buf.normals.data());
    }
    renderer.draw(scene.camera, scene.lights, out.background);
    times.render_s += seconds_since(t0);

    t0 = Clock::now();
    renderer.read_frame(frame);
    times.readback_s += seconds_since(t0);

    t0 = Clock::now();
    for (auto& sink : sinks) sink->write(frame, f);
    times.encode_s += seconds_since(t0);
    ++times.frames;
    progress.update(times.frames);
  }
  const auto t0 = Clock::now();
  for (auto& sink : sinks) sink->finish();
  times.encode_s += seconds_since(t0);
  progress.finish();
  times.wall_s = seconds_since(start);
  return times;
}

std::string describe(const StageTimes& t) {
  const double n = t.frames > 0 ? t.frames : 1;
  char text[512];
  std::snprintf(text, sizeof text,
                "%d frames in %.2f s: simulate %.2f ms/frame, render %.2f ms/frame, read back %.2f ms/frame, "
                "encode %.2f ms/frame",
                t.frames, t.wall_s, 1e3 * t.simulate_s / n, 1e3 * t.render_s / n, 1e3 * t.readback_s / n,
                1e3 * t.encode_s / n);
  return text;
}

}  // namespace systole::app
