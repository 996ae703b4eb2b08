#pragma once
// What every exporter writes from: each organ's render surface (triangles, regions and
// their colours) and its simulated vertex positions at every frame of the clip, with each
// region's activation per frame. Recorded from the world's render-surface positions
// (world::render_positions), whatever body carries them - particles, a lattice or an
// embedded myocardium - or read back from a bake of the same scene.
//
// Inputs:  a loaded scene (and optionally a bake of it, world/bake.h).
// Outputs: a Recording in memory (24 bytes per vertex per frame).
// See also: export/exporter.h (which format gets which recording), docs/export.md.

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.h"

namespace systole::exporter {

/// One organ's surface and its motion.
struct OrganTrack {
  std::string name;
  std::vector<Eigen::Vector3i> triangles;  ///< The full render surface (not the simplified drawn one).
  std::vector<int> vertex_region;          ///< Per vertex: index into region_names, or -1 (the organ's body).
  std::vector<std::string> region_names;
  /// sRGB colour each region is drawn in (render::static_vertex_colors), and the body's for -1.
  std::vector<scene::Color> region_colors;
  scene::Color body_color = scene::Color(0.72, 0.16, 0.14);
  double opacity = 1;  ///< The material's. unit: 1
  bool closed = true;  ///< A closed surface; an open one is drawn two-sided.
  Eigen::Matrix3Xd rest_m;                 ///< The surface at rest. unit: m
  std::vector<Eigen::Matrix3Xd> frames_m;  ///< Positions at every frame. unit: m
  /// activation[f][r]: region r's drive phi at frame f, 0 relaxed .. 1 contracted (as color_by
  /// activation shows it). unit: 1
  std::vector<std::vector<double>> activation;

  int vertex_count() const { return static_cast<int>(rest_m.cols()); }
};

struct Recording {
  std::string scene_name;
  double fps = 30;         ///< Video frames per second: frame k plays at k / fps. unit: 1/s
  double frame_s = 1.0 / 30;  ///< Organ time between two frames (slow motion shows in fps / frame_s). unit: s
  /// The frames are whole cycles after settling (output.loop): the frame after the last is
  /// the first again.
  bool loop = false;
  /// Frames simulated before frame 0 (output.loop's settling, whole loops): frame f is the
  /// simulation's frame start_frame + f, at organ time (start_frame + f) x frame_s. unit: frames
  int start_frame = 0;
  /// The scene's camera at the clip's first frame, placed as the renderer places it
  /// (clip::with_cameras_placed: automatic framing for an output.width x output.height
  /// frame when the scene gives no camera.position), with no motion left.
  scene::Camera camera;
  std::vector<OrganTrack> organs;

  int frame_count() const { return organs.empty() ? 0 : static_cast<int>(organs.front().frames_m.size()); }
};

/// The region a triangle is drawn in: the one most of its corners are in (the first
/// corner's on a three-way tie), so a region's border triangles split fairly between
/// neighbours. -1: the organ's body.
int triangle_region(const OrganTrack& organ, const Eigen::Vector3i& triangle);

/// A file name for organ `o`: `file` itself for a single organ, else `<stem>-<organ><ext>`
/// (the organ's name with anything but letters, digits, '-' and '_' as '_'), for formats
/// that hold one mesh per file.
std::filesystem::path organ_file(const std::filesystem::path& file, const Recording& rec, std::size_t o);

/// Simulates the scene's clip (every frame, output.start_frame settling first) and records
/// it; or, with `from_bake`, reads the positions from that bake after checking it fits the
/// scene (Error(kDataError) naming what differs). A listener on one run of the scene's frame
/// source (world/frame_source.h). Throws what build_world and advance_to_frame throw.
Recording record(const scene::Scene& scene, const std::filesystem::path& from_bake = {});

}  // namespace systole::exporter
