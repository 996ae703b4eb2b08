#pragma once
// The frame loop: simulate -> render -> read back -> anti-alias -> encode, for one scene,
// with the stages overlapped on threads (clip/frame_pipeline.h).

#include <filesystem>
#include <string>
#include <vector>

#include "clip/limits.h"
#include "clip/progress.h"
#include "encode/video_writer.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace systole::clip {

struct RenderRequest {
  std::filesystem::path video;    ///< Video to write (format: video_format()); empty: no video.
  std::filesystem::path png_dir;  ///< Folder for numbered PNG frames; empty: none.
  /// The soundtrack alone as a WAV file (the scene needs `audio:`); empty: none.
  std::filesystem::path wav;
  /// Frames to render and encode (0-based, sorted, no duplicates; app::parse_frame_list);
  /// empty: every frame. The simulation still steps through every frame up to the last
  /// listed one, so frame k is the same image whatever else is rendered. A video needs
  /// consecutive frames (it then holds that range, starting at time 0).
  std::vector<int> frames;
  ProgressStyle progress = ProgressStyle::kNone;
  std::string job;  ///< Names the clip in progress reports; empty: the scene's name.
  /// A bake of this scene (world/bake.h): positions are read from it instead of simulated.
  std::filesystem::path from_bake;
  /// Checked before the world is built (frame size, duration, output size) and before the
  /// first step (vertices, solver substeps); Error(kDataError) names the one exceeded.
  Limits limits;
  /// Simulate, render and encode on three threads at once (app/frame_pipeline.h); false
  /// runs them one after another. The output is the same bits either way.
  bool overlap = true;
};

/// What each stage cost, summed over the clip. Stages overlap, so the sum exceeds wall_s;
/// each is the busy time of its own thread (inflated when the stages contend for cores).
struct StageTimes {
  int frames = 0;          ///< Frames rendered.
  int card_frames = 0;     ///< Title-card frames written before them (their drawing counts as encode_s).
  double simulate_s = 0;   ///< unit: s
  double render_s = 0;     ///< unit: s
  double readback_s = 0;   ///< unit: s
  double antialias_s = 0;  ///< The FXAA pass (render/fxaa.h), if the scene asks for it. unit: s
  double overlay_s = 0;    ///< Drawing the teaching overlays (app/overlay_plan.h) on the frames. unit: s
  double encode_s = 0;     ///< unit: s (video and PNG writing)
  double wall_s = 0;       ///< Whole run including set-up. unit: s
  long long steps = 0;     ///< Solver steps of the clip's one simulation run, summed over its organs.
};

/// Renders the clip (or the requested frames of it). Outputs appear only when complete
/// (temporary file + rename); a failure leaves earlier outputs untouched. PNG frames are
/// named encode::frame_file_name(frame, clip frame count) whatever is selected. Throws
/// systole::Error: kUsage for frames outside the clip, unsorted, or not consecutive with a video.
StageTimes render_clip(const scene::Scene& scene, const RenderRequest& request);

/// "simulate 1.2 ms/frame, render ..." for the end-of-run summary.
std::string describe(const StageTimes& times);

/// The frame's views: one whole-frame view of every surface when the scene has no
/// `views`, else each view in its rectangle (scene::view_rectangles) with the surfaces of its
/// organs (surface_ids[o] is organ o's) and its clip. Cameras are set by set_view_cameras.
std::vector<render::ViewDraw> frame_views(const scene::Scene& scene, const std::vector<int>& surface_ids);

/// Puts every view's camera (its own, else the scene's) where it is at time t_s (unit: s).
void set_view_cameras(const scene::Scene& scene, double t_s, std::vector<render::ViewDraw>& views);

}  // namespace systole::clip
