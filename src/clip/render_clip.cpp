#include "clip/render_clip.h"

#include "clip/video_format.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <numeric>
#include <vector>

#include "clip/camera_framing.h"
#include "clip/camera_motion.h"
#include "clip/ecg_outputs.h"
#include "clip/frame_list.h"
#include "clip/frame_pipeline.h"
#include "clip/overlay_plan.h"
#include "clip/progress.h"
#include "clip/render_detail.h"
#include "clip/soundtrack.h"
#include "clip/text_tracks.h"
#include "audio/wav.h"
#include "encode/webvtt.h"
#include "common/atomic_output.h"
#include "common/error.h"
#include "common/folder_update.h"
#include "encode/png.h"
#include "encode/video_writer.h"
#include "mesh/normals.h"
#include "mesh/strain.h"
#include "overlay/cards.h"
#include "render/color_map.h"
#include "render/fxaa.h"
#include "render/renderer.h"
#include "sim/model.h"
#include "world/frame_source.h"
#include "world/world.h"

namespace systole::clip {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Per vertex: its region's opacity, else the material's; empty when all are the material's.
std::vector<double> vertex_opacity(const scene::Organ& organ, const std::vector<int>& vertex_region) {
  const bool any = std::any_of(organ.regions.begin(), organ.regions.end(), [](const scene::Region& r) { return r.has_opacity; });
  if (!any) return {};
  std::vector<double> opacity(vertex_region.size(), organ.material.opacity);
  for (std::size_t i = 0; i < vertex_region.size(); ++i) {
    const int r = vertex_region[i];
    if (r >= 0 && organ.regions[static_cast<std::size_t>(r)].has_opacity) opacity[i] = organ.regions[static_cast<std::size_t>(r)].opacity;
  }
  return opacity;
}

/// One organ's surface for one frame, as the renderer takes it (allocated once per slot).
struct SurfaceBuffers {
  Eigen::Matrix3Xd mesh_positions;  ///< The render mesh's vertices this frame (world::render_positions). unit: m
  std::vector<float> positions, normals;  ///< xyz per vertex. unit: m, 1
  std::vector<float> colors;        ///< sRGB per vertex, for colour maps that change (strain, activation).
  std::vector<double> values;       ///< The mapped value per vertex. unit: 1
  std::vector<double> region_phi;   ///< Activation per region this frame. unit: 1
};

/// An organ coloured by a value that changes every frame.
struct DynamicColors {
  render::ColorMap map;
  scene::ColorBy by = scene::ColorBy::kStrain;
  std::optional<mesh::VertexStrain> strain;  ///< kStrain: the mesh's edges at rest.
};

/// Fills buf.colors from the organ's colour map at time t_s (unit: s).
void map_colors(const DynamicColors& dynamic, const world::OrganBody& body, double t_s, SurfaceBuffers& buf) {
  if (dynamic.by == scene::ColorBy::kStrain) {
    dynamic.strain->compute(buf.mesh_positions, buf.values);
  } else {
    // Activation phi(t) of each vertex's region; 0 for the undriven body.
    const std::vector<int>& vertex_region = body.geometry.vertex_region;
    sim::region_activations(body.model, t_s, buf.region_phi);
    buf.values.resize(vertex_region.size());
    for (std::size_t v = 0; v < vertex_region.size(); ++v) {
      buf.values[v] = vertex_region[v] >= 0 ? buf.region_phi[static_cast<std::size_t>(vertex_region[v])] : 0.0;
    }
  }
  for (std::size_t v = 0; v < buf.values.size(); ++v) {
    const scene::Color c = dynamic.map.at(buf.values[v]);
    for (int k = 0; k < 3; ++k) buf.colors[3 * v + k] = static_cast<float>(c[k]);
  }
}

/// Frames in flight between two stages. Three: one being written, one being read, and one
/// ready, so a stage that is briefly slower does not stall the other.
constexpr int kPipelineDepth = 3;


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

/// Every organ's surface as the renderer holds it, and the buffers each pipeline slot fills.
struct ClipSurfaces {
  std::vector<std::vector<SurfaceBuffers>> slots;  ///< slots[k][o]: organ o of the frame in slot k.
  std::vector<int> ids;                            ///< The renderer's surface id of each organ.
  std::vector<std::vector<Eigen::Vector3i>> drawn; ///< The triangles drawn of each organ (clip/render_detail.h).
  std::vector<std::optional<DynamicColors>> dynamic;
};

ClipSurfaces add_surfaces(render::Renderer& renderer, const scene::Scene& scene, const world::World& world) {
  ClipSurfaces s;
  s.slots.assign(kPipelineDepth, std::vector<SurfaceBuffers>(world.organs.size()));
  s.dynamic.resize(world.organs.size());
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& body = world.organs[o];
    const auto& organ = scene.organs[o];
    const auto& surface = body.geometry.mesh.surface;
    RenderDetail detail = render_detail(scene, world, o);
    s.ids.push_back(renderer.add_surface(detail.triangles,
                                         render::static_vertex_colors(organ, body.geometry.vertex_region),
                                         organ.material, vertex_opacity(organ, body.geometry.vertex_region)));
    if (organ.clip.enabled) renderer.set_clip(s.ids.back(), organ.clip);
    // An open surface (an atlas part, a sheet) would show nothing through its holes or
    // from behind with its back faces culled.
    renderer.set_two_sided(s.ids.back(), body.geometry.report.closed() ? -1 : detail.two_sided_from);
    if (!detail.enclosed.empty()) renderer.set_enclosed(s.ids.back(), detail.enclosed);
    s.drawn.push_back(std::move(detail.triangles));
    if (const render::OrganColorMap map = render::organ_color_map(organ); map.has) {
      s.dynamic[o].emplace();
      s.dynamic[o]->map = map.map;
      s.dynamic[o]->by = organ.color_by;
      if (organ.color_by == scene::ColorBy::kStrain) s.dynamic[o]->strain.emplace(surface.positions, surface.triangles);
    }
    for (auto& slot : s.slots) {
      slot[o].positions.resize(3 * surface.positions.size());
      slot[o].normals.resize(3 * surface.positions.size());
      if (s.dynamic[o]) slot[o].colors.resize(3 * surface.positions.size());
    }
  }
  return s;
}

/// The title cards before the clip and the text tracks timed after them, worked out once
/// for the video, its soundtrack and the WebVTT file beside it.
struct ClipText {
  int card_frames = 0;  ///< Title-card frames of the scene (all cards).
  double cards_s = 0;   ///< Their length in this video: 0 unless it starts at the clip's first frame. unit: s
  std::vector<encode::TextCue> captions;
  std::vector<encode::ChapterMark> chapters;
};

ClipText clip_text(const scene::Scene& scene, const std::vector<int>& frames) {
  ClipText t;
  const std::vector<int> cards = card_frame_counts(scene);
  t.card_frames = std::accumulate(cards.begin(), cards.end(), 0);
  t.cards_s = frames.front() == 0 ? t.card_frames / scene.output.fps : 0.0;
  t.captions = caption_cues(scene, frames.front(), frames.back(), t.cards_s);
  t.chapters = chapter_marks(scene, frames.front(), frames.back(), t.cards_s);
  return t;
}

/// The video's sink with its soundtrack, subtitle track and chapters (GIF: the frames only).
std::unique_ptr<encode::FrameSink> open_video_sink(const scene::Scene& scene, const RenderRequest& request,
                                                   const ClipText& text, const audio::Soundtrack* sound) {
  if (request.video.empty()) return nullptr;
  encode::VideoSettings settings = video_settings(scene.output, video_format(scene, request.video));
  if (settings.format != encode::VideoFormat::kGif) {
    if (sound != nullptr) {
      settings.audio = sound->samples;
      settings.audio_rate_hz = sound->sample_rate_hz;
    }
    settings.subtitles = text.captions;
    settings.chapters = text.chapters;
  }
  return encode::open_video(request.video, settings);
}

std::unique_ptr<encode::FrameSink> open_png_sink(const RenderRequest& request, int frame_count) {
  if (request.png_dir.empty()) return nullptr;
  return std::make_unique<encode::PngSequenceWriter>(request.png_dir, frame_count);
}

/// One clip's frames: what the three stages (clip/frame_pipeline.h) share. Made before the
/// source runs, since its volume traces listen to every frame; the sinks are opened next
/// (open_sinks), before the first frame, so a bad output path fails before any drawing. Each
/// stage adds to its own times only (one thread each).
class ClipFrames {
 public:
  ClipFrames(const scene::Scene& scene, const std::vector<int>& frames, world::FrameSource& source,
             render::Renderer& renderer, StageTimes& times)
      : scene_(scene), out_(scene.output), frames_(frames), source_(source), world_(source.world()),
        renderer_(renderer), times_(times), surfaces_(add_surfaces(renderer, scene, world_)),
        // The views: each a rectangle with its organs' surfaces; the render stage moves their cameras.
        views_(frame_views(scene, surfaces_.ids)),
        cards_(scene),
        // Overlays: anchors captured with the positions (produce), handed on through the render
        // stage's slots (produce may refill its slot before consume is done), drawn after FXAA.
        overlay_(scene, world_),
        overlay_produced_(kPipelineDepth),
        overlay_rendered_(kPipelineDepth) {
    if (!overlay_.volume_organs().empty()) {
      // A volume trace listens to every frame of the run, rendered or not (or baked).
      source_.on_frame([this](int frame) {
        for (int o : overlay_.volume_organs()) {
          source_.positions(o, volume_positions_);
          overlay_.record_volume(o, frame, volume_positions_);
        }
      });
    }
    frame_positions_.resize(world_.organs.size());
    images_.assign(kPipelineDepth, Image(out_.width, out_.height));
  }

  /// Opens the video (with its soundtrack and text tracks) and the PNG folder. Title cards
  /// open the video when it starts at the clip's start; PNG frames are the clip's frames only
  /// (with their captions), numbered as always.
  void open_sinks(const RenderRequest& request, const ClipText& text, const audio::Soundtrack* sound) {
    video_ = open_video_sink(scene_, request, text, sound);
    png_ = open_png_sink(request, out_.frame_count());
    video_offset_ = video_ && frames_.front() == 0 ? cards_.card_frames() : 0;
  }

  /// Writes the title cards before the clip's first frame, when the video starts there.
  void write_cards() {
    if (video_offset_ == 0) return;
    const auto t0 = Clock::now();
    Image card(out_.width, out_.height);
    for (int k = 0; k < video_offset_; ++k) {
      cards_.draw_card(k, card);
      video_->write(card, k);
    }
    times_.card_frames = video_offset_;
    times_.encode_s += seconds_since(t0);
  }

  /// Brings the source to frame i (simulated, or replayed) and fills `slot` from it:
  /// positions, normals, colours, overlay anchors.
  void produce(int i, int slot) {
    const int f = frames_[static_cast<std::size_t>(i)];
    auto t0 = Clock::now();
    source_.advance_to(f);  // Through every frame in between.
    for (std::size_t o = 0; o < world_.organs.size(); ++o) {
      fill_surface(f, o, surfaces_.slots[static_cast<std::size_t>(slot)][o]);
    }
    times_.simulate_s += seconds_since(t0);
    if (!overlay_.empty()) {
      t0 = Clock::now();
      overlay_.capture(f, frame_positions_, overlay_produced_[static_cast<std::size_t>(slot)]);
      times_.simulate_s += seconds_since(t0);  // This thread's own sum: the capture is counted with it.
    }
  }

  /// Draws the frame in `slot` and reads it back.
  void render(int i, int slot) {
    auto t0 = Clock::now();
    for (std::size_t o = 0; o < surfaces_.ids.size(); ++o) {
      const auto& buf = surfaces_.slots[static_cast<std::size_t>(slot)][o];
      renderer_.update_surface(surfaces_.ids[o], buf.positions.data(), buf.normals.data());
      if (surfaces_.dynamic[o]) renderer_.update_colors(surfaces_.ids[o], buf.colors.data());
    }
    const double t_s = frames_[static_cast<std::size_t>(i)] / out_.fps;
    set_view_cameras(scene_, t_s, views_);
    renderer_.draw(views_, scene_.lights, out_.background);
    times_.render_s += seconds_since(t0);
    t0 = Clock::now();
    renderer_.read_frame(images_[static_cast<std::size_t>(slot)]);
    times_.readback_s += seconds_since(t0);
    if (!overlay_.empty()) {
      overlay_rendered_[static_cast<std::size_t>(slot)] = overlay_produced_[static_cast<std::size_t>(slot)];
    }
  }

  /// Anti-aliases the frame in `slot`, draws the overlays and captions on it and encodes it.
  void consume(int i, int slot) {
    Image& image = images_[static_cast<std::size_t>(slot)];
    auto t0 = Clock::now();
    if (out_.antialias == scene::Antialias::kFxaa) fxaa_.apply(image);
    times_.antialias_s += seconds_since(t0);
    if (!overlay_.empty()) {
      // After FXAA: text and lines stay crisp.
      t0 = Clock::now();
      overlay_.draw(image, overlay_rendered_[static_cast<std::size_t>(slot)]);
      times_.overlay_s += seconds_since(t0);
    }
    t0 = Clock::now();
    const int f = frames_[static_cast<std::size_t>(i)];
    if (out_.burn_captions) cards_.draw_captions(f, image);
    if (video_) video_->write(image, video_offset_ + f);
    if (png_) png_->write(image, f);
    times_.encode_s += seconds_since(t0);
    ++times_.frames;
  }

  void finish() {
    const auto t0 = Clock::now();
    if (video_) video_->finish();
    if (png_) png_->finish();
    times_.encode_s += seconds_since(t0);
  }

 private:
  /// Organ o's surface at frame f, from the source.
  void fill_surface(int f, std::size_t o, SurfaceBuffers& buf) {
    source_.positions(static_cast<int>(o), buf.mesh_positions);
    const Eigen::Index n = buf.mesh_positions.cols();
    const double* x = buf.mesh_positions.data();
    for (Eigen::Index k = 0; k < 3 * n; ++k) buf.positions[k] = static_cast<float>(x[k]);
    // The drawn triangles' normals: a simplified mesh is shaded as it is drawn (and a
    // vertex no drawn triangle uses is never seen).
    mesh::vertex_normals(x, static_cast<int>(n), surfaces_.drawn[o], buf.normals.data());
    if (surfaces_.dynamic[o]) map_colors(*surfaces_.dynamic[o], world_.organs[o], out_.organ_time_s(f), buf);
    frame_positions_[o] = &buf.mesh_positions;
  }

  const scene::Scene& scene_;
  const scene::Output& out_;
  const std::vector<int>& frames_;
  world::FrameSource& source_;
  const world::World& world_;
  render::Renderer& renderer_;
  StageTimes& times_;
  ClipSurfaces surfaces_;
  std::vector<render::ViewDraw> views_;
  std::unique_ptr<encode::FrameSink> video_, png_;
  overlay::CardPainter cards_;
  int video_offset_ = 0;
  OverlayPlan overlay_;
  std::vector<OverlayFrame> overlay_produced_, overlay_rendered_;
  Eigen::Matrix3Xd volume_positions_;
  std::vector<const Eigen::Matrix3Xd*> frame_positions_;
  std::vector<Image> images_;
  render::Fxaa fxaa_;
};

/// The run's claims on what it writes, taken before the world is built: a second run of the
/// same output is refused at once, not after the costly set-up. The writers opened later
/// join them (common/atomic_output.h). A PNG folder is claimed as a whole, named as its
/// writer names it (common/folder_update.h), its parents made first as its writer would.
std::deque<OutputLock> claim_outputs(const RenderRequest& request) {
  std::deque<OutputLock> claims;  // Locks neither copy nor move: a deque builds them in place.
  if (!request.video.empty()) claims.emplace_back(request.video);
  if (!request.wav.empty()) claims.emplace_back(request.wav);
  if (!request.png_dir.empty()) {
    const std::filesystem::path folder = update_folder_of(request.png_dir);
    std::error_code ec;
    if (folder.has_parent_path()) std::filesystem::create_directories(folder.parent_path(), ec);
    if (ec) throw Error(ExitCode::kCannotCreate, "cannot create '" + folder.parent_path().string() + "': " + ec.message());
    claims.emplace_back(folder);
  }
  return claims;
}

}  // namespace

StageTimes render_clip(const scene::Scene& given, const RenderRequest& request) {
  const auto start = Clock::now();
  StageTimes times;
  const auto& out = given.output;
  const std::vector<int> frames = selected_frames(request, out.frame_count());
  check_scene_limits(given, {static_cast<int>(frames.size()), !request.video.empty(), !request.png_dir.empty()},
                     request.limits);
  apply_to_mesh_reader(request.limits);
  if (!given.audio.enabled && !request.wav.empty()) {
    throw Error(ExitCode::kUsage, "--wav: " + given.path + " has no audio: section, so there is no soundtrack to write");
  }
  const std::deque<OutputLock> claims = claim_outputs(request);
  // The clip's one run of the simulation: the pictures, the volume traces and the sound listen to it.
  world::FrameSource source(given);
  check_world_limits(given, source.world(), request.limits);
  const scene::Scene scene = with_cameras_placed(given, source.world());
  check_organs_in_view(scene, source.world());
  const int msaa = out.antialias == scene::Antialias::kMsaa4 ? 4 : out.antialias == scene::Antialias::kMsaa2 ? 2 : 0;
  render::Renderer renderer(out.width, out.height, msaa);
  if (!request.from_bake.empty()) source.replay_bake(request.from_bake, scene);
  ClipFrames clip(scene, frames, source, renderer, times);
  const ClipText text = clip_text(scene, frames);
  // The soundtrack first, for the video and --wav: the source simulates ahead with the sound
  // listening, and the frames below replay what it kept.
  std::optional<audio::Soundtrack> sound;
  if (scene.audio.enabled && (!request.wav.empty() || !request.video.empty())) {
    const auto t0 = Clock::now();
    sound = make_soundtrack(scene, source, frames, text.card_frames);
    times.simulate_s += seconds_since(t0);
  }
  clip.open_sinks(request, text, sound ? &*sound : nullptr);
  Progress progress(request.job.empty() ? scene.name : request.job, static_cast<int>(frames.size()),
                    request.progress);
  PipelineStages stages;
  stages.produce = [&](int i, int slot) { clip.produce(i, slot); };
  stages.render = [&](int i, int slot) { clip.render(i, slot); };
  stages.consume = [&](int i, int slot) {
    clip.consume(i, slot);
    progress.update(times.frames);
  };
  clip.write_cards();
  run_frame_pipeline(static_cast<int>(frames.size()), kPipelineDepth, request.overlap, stages);
  clip.finish();
  if (!request.wav.empty()) audio::write_wav(request.wav, *sound);
  if (!request.video.empty() && !scene.captions.empty()) encode::write_webvtt(webvtt_path(request.video), text.captions);
  if (!request.video.empty()) write_ecg_outputs(source.world(), request.video, out.duration_s);
  progress.finish();
  times.steps = source.steps_taken();
  times.wall_s = seconds_since(start);
  return times;
}

std::vector<render::ViewDraw> frame_views(const scene::Scene& scene, const std::vector<int>& surface_ids) {
  std::vector<render::ViewDraw> views;
  if (scene.views.empty()) {
    views.emplace_back();  // The whole frame, every surface, no cut.
    views.back().camera = scene.camera;
    return views;
  }
  const auto rects = scene::view_rectangles(scene.output.width, scene.output.height, static_cast<int>(scene.views.size()));
  for (std::size_t v = 0; v < scene.views.size(); ++v) {
    const scene::View& view = scene.views[v];
    render::ViewDraw draw;
    draw.camera = view.has_camera ? view.camera : scene.camera;
    draw.rect = rects[v];
    draw.clip = view.clip;
    for (const std::string& name : view.organs) {
      for (std::size_t o = 0; o < scene.organs.size(); ++o) {
        if (scene.organs[o].name == name) draw.surfaces.push_back(surface_ids[o]);
      }
    }
    views.push_back(draw);
  }
  return views;
}

void set_view_cameras(const scene::Scene& scene, double t_s, std::vector<render::ViewDraw>& views) {
  for (std::size_t v = 0; v < views.size(); ++v) {
    const bool own = v < scene.views.size() && scene.views[v].has_camera;
    views[v].camera = camera_at(own ? scene.views[v].camera : scene.camera, t_s);
  }
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
  std::string line = text;
  if (t.card_frames > 0) line += "; encode includes " + std::to_string(t.card_frames) + " title-card frames";
  return line;
}

}  // namespace systole::clip
