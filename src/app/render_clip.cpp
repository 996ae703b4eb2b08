#include "app/render_clip.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "app/progress.h"
#include "app/world.h"
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

}  // namespace

std::filesystem::path default_video_path(const scene::Scene& scene) {
  if (!scene.output.file.empty()) return scene.output.file;
  return std::filesystem::path("out") / (scene.name + ".mp4");
}

StageTimes render_clip(const scene::Scene& scene, const RenderRequest& request) {
  const auto start = Clock::now();
  StageTimes times;
  World world = build_world(scene);
  const auto& out = scene.output;
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
  const int frame_count = out.frame_count();
  if (!request.video.empty()) {
    encode::VideoSettings video{out.width, out.height, out.fps, out.crf, out.preset, 0};
    sinks.push_back(std::make_unique<encode::Mp4Writer>(request.video, video));
  }
  if (!request.png_dir.empty()) {
    sinks.push_back(std::make_unique<encode::PngSequenceWriter>(request.png_dir, frame_count));
  }

  Image frame(out.width, out.height);
  Progress progress(scene.name, frame_count, request.show_progress);
  for (int f = 0; f < frame_count; ++f) {
    auto t0 = Clock::now();
    advance_to_frame(world, f);
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
    progress.update(f + 1);
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
