#include "export/recording.h"

#include <cctype>

#include "clip/camera_framing.h"
#include "clip/camera_motion.h"
#include "render/color_map.h"
#include "sim/model.h"
#include "world/frame_source.h"

namespace systole::exporter {
namespace {

/// The organ's surface, regions and colours as the renderer draws them (before motion).
OrganTrack surface_of(const scene::Organ& organ, const world::OrganBody& body) {
  OrganTrack t;
  t.name = organ.name;
  const auto& surface = body.geometry.mesh.surface;
  t.triangles = surface.triangles;
  t.vertex_region = body.geometry.vertex_region;
  t.rest_m.resize(3, static_cast<Eigen::Index>(surface.positions.size()));
  for (std::size_t v = 0; v < surface.positions.size(); ++v) t.rest_m.col(static_cast<Eigen::Index>(v)) = surface.positions[v];
  t.body_color = organ.material.color;
  t.opacity = organ.material.opacity;
  t.closed = body.geometry.report.closed();
  // A region's colour is the one its vertices are drawn in: the renderer's own table, so
  // color_by region and material (and a region's `color`) read the same in every viewer.
  const std::vector<scene::Color> vertex_colors = render::static_vertex_colors(organ, t.vertex_region);
  t.region_colors.assign(organ.regions.size(), organ.material.color);
  std::vector<bool> seen(organ.regions.size(), false);
  for (std::size_t v = 0; v < t.vertex_region.size() && v < vertex_colors.size(); ++v) {
    const int r = t.vertex_region[v];
    if (r >= 0 && !seen[static_cast<std::size_t>(r)]) {
      t.region_colors[static_cast<std::size_t>(r)] = vertex_colors[v];
      seen[static_cast<std::size_t>(r)] = true;
    }
  }
  for (const auto& region : organ.regions) t.region_names.push_back(region.name);
  return t;
}

}  // namespace

int triangle_region(const OrganTrack& organ, const Eigen::Vector3i& t) {
  if (organ.vertex_region.empty()) return -1;
  const int a = organ.vertex_region[static_cast<std::size_t>(t[0])];
  const int b = organ.vertex_region[static_cast<std::size_t>(t[1])];
  const int c = organ.vertex_region[static_cast<std::size_t>(t[2])];
  return (b == c && a != b) ? b : a;
}

std::filesystem::path organ_file(const std::filesystem::path& file, const Recording& rec, std::size_t o) {
  if (rec.organs.size() == 1) return file;
  std::string name = rec.organs[o].name;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return file.parent_path() / (file.stem().string() + "-" + name + file.extension().string());
}

Recording record(const scene::Scene& scene, const std::filesystem::path& from_bake) {
  world::FrameSource source(scene);
  const world::World& world = source.world();
  Recording rec;
  rec.scene_name = scene.name;
  rec.fps = scene.output.fps;
  rec.frame_s = scene.output.frame_period_s();
  rec.loop = scene.output.loop;
  rec.start_frame = scene.output.start_frame;
  // Placed on the organs at rest, before any step, as render_clip places it.
  rec.camera = clip::camera_at(clip::with_cameras_placed(scene, world).camera, 0);
  for (std::size_t o = 0; o < world.organs.size(); ++o) rec.organs.push_back(surface_of(scene.organs[o], world.organs[o]));
  if (!from_bake.empty()) source.replay_bake(from_bake, scene);
  const int frames = scene.output.frame_count();
  for (auto& track : rec.organs) {
    track.frames_m.resize(static_cast<std::size_t>(frames));
    track.activation.resize(static_cast<std::size_t>(frames));
  }
  // The recorder is a listener on the run: every frame's positions and activations.
  source.on_frame([&](int f) {
    // The organ time of clip frame f, where the world stepped it (world::advance_to_frame).
    const double t_s = scene.output.organ_time_s(f);
    for (std::size_t o = 0; o < world.organs.size(); ++o) {
      auto& track = rec.organs[o];
      source.positions(static_cast<int>(o), track.frames_m[static_cast<std::size_t>(f)]);
      sim::region_activations(world.organs[o].model, t_s, track.activation[static_cast<std::size_t>(f)]);
    }
  });
  source.advance_to(frames - 1);
  return rec;
}

}  // namespace systole::exporter
