#include "clip/overlay_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "clip/camera_motion.h"
#include "mesh/anatomy.h"
#include "overlay/title.h"
#include "render/camera_matrices.h"
#include "render/color_map.h"
#include "scene/tree.h"
#include "sim/drive.h"
#include "sim/model.h"
#include "world/heart_ecg.h"

namespace systole::clip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Analytic signals (activation, ECG) are sampled finely enough for a QRS complex. unit: Hz
constexpr double kSignalRateHz = 500;
/// The R wave leads the contraction it triggers (the electromechanical delay). unit: s
constexpr double kElectromechanicalDelayS = 0.04;
/// Atria driven faster than this flutter or fibrillate: no P waves. unit: Hz (240/min)
constexpr double kFibrillationHz = 4.0;
/// Half the swing of the f-waves that replace them. unit: mV
constexpr double kFibrillationMv = 0.05;

std::string spaced(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

plot::Rgb to_rgb(const scene::Color& c) {
  plot::Rgb out{};
  for (int k = 0; k < 3; ++k) out[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
  return out;
}

int organ_index(const scene::Scene& scene, const std::string& name) {
  for (std::size_t o = 0; o < scene.organs.size(); ++o)
    if (scene.organs[o].name == name) return static_cast<int>(o);
  return 0;  // Empty name: the first organ (the schema checked every other name).
}

int region_index(const scene::Organ& organ, const std::string& name) {
  for (std::size_t r = 0; r < organ.regions.size(); ++r)
    if (organ.regions[r].name == name) return static_cast<int>(r);
  return -1;
}

/// A region's beat boundaries (sim::Model::beat_boundaries); empty (regular beats) when it has none.
const std::vector<double>& beats_of(const sim::Model& model, int region) {
  static const std::vector<double> regular;
  return region >= 0 && static_cast<std::size_t>(region) < model.beat_boundaries.size()
             ? model.beat_boundaries[static_cast<std::size_t>(region)]
             : regular;
}

/// Activation phi(t) of the trace's region at kSignalRateHz; trace.values has the sample count.
void fill_activation_trace(const scene::Organ& organ, const sim::Model& model, const scene::TraceOverlay& t,
                           overlay::Trace& trace) {
  const int r = region_index(organ, t.region);
  const auto& drive = model.regions[static_cast<std::size_t>(r)].drive;
  const auto& beats = beats_of(model, r);
  trace.title = "activation: " + spaced(t.region);
  trace.color = {255, 196, 90};
  trace.min = -0.05;
  trace.max = 1.05;
  for (std::size_t i = 0; i < trace.values.size(); ++i)
    trace.values[i] = sim::activation(drive, double(i) / kSignalRateHz, model.ramp_s, beats);
}

/// A synthetic ECG at kSignalRateHz: an R wave before each beat of the trace's region, P waves
/// (or f-waves) from the atrial region's; trace.values has the sample count.
void fill_ecg_trace(const scene::Organ& organ, const sim::Model& model, const scene::TraceOverlay& t, double clip_s,
                    overlay::Trace& trace) {
  const int r = region_index(organ, t.region);
  const auto& drive = model.regions[static_cast<std::size_t>(r)].drive;
  const auto& beats = beats_of(model, r);
  trace.title = "ECG (synthetic): beats of " + spaced(t.region);
  trace.color = {120, 230, 150};
  trace.min = -0.45;
  trace.max = 1.15;
  std::vector<double> r_times = sim::beat_start_times(drive, beats, model.ramp_s, clip_s + 1.0);
  for (double& r_time : r_times) r_time -= kElectromechanicalDelayS;
  // P waves: from the atrial region's beats when one is named, each depolarisation the
  // same delay before the contraction it triggers; atria faster than any sinus rhythm
  // fibrillate or flutter: no P waves, but f-waves following their drive.
  const int a = t.atria.empty() ? -1 : region_index(organ, t.atria);
  const sim::Drive* atria = a >= 0 ? &model.regions[static_cast<std::size_t>(a)].drive : nullptr;
  const auto& atrial_beats = beats_of(model, a);
  const bool fibrillating = atria && atria->rate_hz > kFibrillationHz;
  std::vector<double> p_times;
  if (atria && !fibrillating) {
    p_times = sim::beat_start_times(*atria, atrial_beats, model.ramp_s, clip_s + 1.0);
    for (double& p_time : p_times) p_time -= kElectromechanicalDelayS;
  }
  for (std::size_t i = 0; i < trace.values.size(); ++i) {
    const double time = double(i) / kSignalRateHz;
    trace.values[i] = overlay::ecg_value(time, r_times, atria ? &p_times : nullptr);
    if (fibrillating) {
      trace.values[i] += kFibrillationMv * (2 * sim::activation(*atria, time, model.ramp_s, atrial_beats) - 1);
    }
  }
}

/// A lead of the organ's computed ECG (world/heart_ecg.h); trace.values has the sample count.
void fill_computed_ecg_trace(const electro::Ecg& ecg, const scene::TraceOverlay& t, overlay::Trace& trace) {
  const std::vector<double>& lead = *ecg.lead(t.lead);
  // No running readout: a monitor's ECG shows the wave, and its value near the baseline
  // would flicker through meaningless digits.
  trace.title = "ECG lead " + t.lead + " (mV)";
  trace.color = {120, 230, 150};
  for (std::size_t i = 0; i < trace.values.size(); ++i) trace.values[i] = i < lead.size() ? lead[i] : kNaN;
  const auto [lo, hi] = std::minmax_element(lead.begin(), lead.end());
  const double margin = 0.1 * std::max(*hi - *lo, 0.2);
  trace.min = *lo - margin;
  trace.max = *hi + margin;
}

}  // namespace

OverlayPlan::~OverlayPlan() = default;

OverlayPlan::OverlayPlan(const scene::Scene& scene, const world::World& world) : spec_(scene.overlay) {
  width_ = scene.output.width;
  height_ = scene.output.height;
  fps_ = scene.output.fps;
  plan_views(scene);
  const bool titled = std::any_of(views_.begin(), views_.end(), [](const ViewFrame& v) { return !v.title.empty(); });
  empty_ = spec_.empty() && !titled;
  if (empty_) return;
  if (spec_.labels.enabled) plan_labels(scene, world);
  if (spec_.legend.enabled) plan_legend(scene, world);
  for (std::size_t i = 0; i < spec_.traces.size(); ++i) plan_trace(scene, world, spec_.traces[i], static_cast<int>(i));
  if (spec_.ecg_sheet.enabled) plan_ecg_sheet(scene, world);
}

void OverlayPlan::plan_ecg_sheet(const scene::Scene& scene, const world::World& world) {
  const int o = organ_index(scene, spec_.ecg_sheet.organ);
  const electro::Ecg& ecg = computed_ecg(world, o, scene.output.duration_s);  // The traces' clip length.
  ecg_sheet_ = {"Computed 12-lead ECG of " + scene.organs[static_cast<std::size_t>(o)].name, ecg.rate_hz, ecg.start_s,
                ecg.leads, ecg.mv};
}

const electro::Ecg& OverlayPlan::computed_ecg(const world::World& world, int organ, double clip_s) {
  auto it = ecgs_.find(organ);
  if (it == ecgs_.end()) {
    // One sample past the clip's end, so the last frame's time has a sample.
    const world::OrganBody& body = world.organs[static_cast<std::size_t>(organ)];
    it = ecgs_.emplace(organ, *world::organ_ecg(body, clip_s + 1.0 / kSignalRateHz, kSignalRateHz)).first;
  }
  return it->second;
}

void OverlayPlan::plan_views(const scene::Scene& scene) {
  // The views labels are placed in and titled: the scene's, as the renderer lays them out.
  if (scene.views.empty()) {
    views_.push_back({scene.camera, {0, 0, width_, height_}, ""});
  } else {
    const auto rects = scene::view_rectangles(width_, height_, static_cast<int>(scene.views.size()));
    for (std::size_t v = 0; v < scene.views.size(); ++v) {
      const scene::View& view = scene.views[v];
      views_.push_back({view.has_camera ? view.camera : scene.camera, rects[v], view.title});
    }
  }
}

void OverlayPlan::plan_labels(const scene::Scene& scene, const world::World& world) {
  auto view_of = [&](const std::string& organ) {
    for (std::size_t v = 0; v < scene.views.size(); ++v) {
      const auto& names = scene.views[v].organs;
      if (names.empty() || std::find(names.begin(), names.end(), organ) != names.end()) return static_cast<int>(v);
    }
    return scene.views.empty() ? 0 : -1;
  };
  // The view asked for, if it shows the organ.
  auto chosen_view = [&](const std::string& organ) {
    for (std::size_t v = 0; v < scene.views.size(); ++v) {
      if (scene.views[v].title != spec_.labels.view) continue;
      const auto& names = scene.views[v].organs;
      return names.empty() || std::find(names.begin(), names.end(), organ) != names.end() ? static_cast<int>(v) : -1;
    }
    return -1;
  };
  Eigen::Matrix3Xd rest;
  for (std::size_t o = 0; o < scene.organs.size(); ++o) {
    const auto& organ = scene.organs[o];
    if (!spec_.labels.organ.empty() && spec_.labels.organ != organ.name) continue;
    const int view = spec_.labels.view.empty() ? view_of(organ.name) : chosen_view(organ.name);
    if (view < 0) continue;  // In no view: nowhere to label it.
    // The cut this organ has in that view: its own, else the view's. A region is anchored on
    // the vertices the cut keeps (at rest), so a label points at what can be seen.
    const scene::ClipPlane* cut = &organ.clip;
    if (!cut->enabled && !scene.views.empty()) cut = &scene.views[static_cast<std::size_t>(view)].clip;
    world::render_positions(world.organs[o], rest);
    const auto kept = [&](int v) { return !cut->enabled || cut->normal.dot(rest.col(v) - cut->point_m) >= 0; };
    const auto& vertex_region = world.organs[o].geometry.vertex_region;
    for (std::size_t r = 0; r < organ.regions.size(); ++r) {
      const auto& wanted = spec_.labels.regions;
      if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), organ.regions[r].name) == wanted.end()) continue;
      LabelTarget t{static_cast<int>(o), view, spaced(organ.regions[r].name), {}};
      for (std::size_t v = 0; v < vertex_region.size(); ++v)
        if (vertex_region[v] == static_cast<int>(r) && kept(static_cast<int>(v))) t.vertices.push_back(static_cast<int>(v));
      if (!t.vertices.empty()) targets_.push_back(std::move(t));  // Taken whole by a later region, or cut away.
    }
  }
}

void OverlayPlan::plan_legend(const scene::Scene& scene, const world::World& world) {
  const int o = organ_index(scene, spec_.legend.organ);
  const auto& organ = scene.organs[static_cast<std::size_t>(o)];
  bool body_shows = false;  // Some vertex keeps the organ's own colour.
  for (int r : world.organs[static_cast<std::size_t>(o)].geometry.vertex_region)
    body_shows = body_shows || r < 0 || !organ.regions[static_cast<std::size_t>(r)].has_color;
  const render::OrganColorMap scalar = render::organ_color_map(organ);
  if (scalar.has) {
    // Coloured by strain or activation: the key is a colour bar of the renderer's own map.
    const render::ColorMap& map = scalar.map;
    color_bar_.label = map.quantity;
    color_bar_.min = map.lo;
    color_bar_.max = map.hi;
    for (int k = 0; k <= 32; ++k) color_bar_.colors.push_back(to_rgb(map.at(map.lo + (map.hi - map.lo) * k / 32.0)));
  } else if (organ.color_by == scene::ColorBy::kRegion) {
    for (const render::RegionSwatch& swatch : render::region_legend(organ)) {
      legend_.push_back({spaced(swatch.name), to_rgb(swatch.color)});
    }
  } else {
    for (const auto& region : organ.regions)
      if (region.has_color) legend_.push_back({spaced(region.name), to_rgb(region.color)});
    if (body_shows) legend_.push_back({spaced(organ.name), to_rgb(organ.material.color)});
  }
}

void OverlayPlan::plan_trace(const scene::Scene& scene, const world::World& world, const scene::TraceOverlay& t,
                             int index) {
  const double clip_s = scene.output.duration_s;
  const int o = organ_index(scene, t.organ);
  const auto& organ = scene.organs[static_cast<std::size_t>(o)];
  overlay::Trace trace;
  trace.window_s = t.window_s > 0 ? t.window_s : clip_s;
  trace.clip_s = clip_s;
  int series = -1;
  if (t.signal == scene::TraceSignal::kVolume) {
    const mesh::OrganMesh& mesh = world.organs[static_cast<std::size_t>(o)].geometry.mesh;
    VolumeSeries s;
    s.organ = o;
    if (t.chamber.empty()) {
      s.triangles = mesh.surface.triangles;
    } else {
      const mesh::Cavity* found = mesh.anatomy.cavity(t.chamber);
      if (found == nullptr) {
        std::string names;
        for (const mesh::Cavity& c : mesh.anatomy.cavities) names += (names.empty() ? "" : ", ") + c.name;
        scene::fail(t.origin, "overlay.traces[" + std::to_string(index) + "].chamber",
                    "organ '" + organ.name + "' has no chamber named '" + t.chamber + "' (" +
                        (names.empty() ? "its mesh has no generated anatomy, e.g. mesh: {procedural: anatomical_heart}"
                                       : "chambers: " + names) +
                        ")");
      }
      s.chamber = *found;
    }
    trace.title = "volume: " + spaced(t.chamber.empty() ? organ.name : t.chamber);
    trace.unit = "mL";
    trace.color = {120, 200, 255};
    trace.sample_dt_s = 1.0 / fps_;
    s.mL.assign(static_cast<std::size_t>(scene.output.frame_count()), kNaN);
    series = static_cast<int>(series_.size());
    series_.push_back(std::move(s));
    if (std::find(volume_organs_.begin(), volume_organs_.end(), o) == volume_organs_.end()) volume_organs_.push_back(o);
  } else {
    const auto n = static_cast<std::size_t>(std::ceil(clip_s * kSignalRateHz)) + 1;
    trace.sample_dt_s = 1.0 / kSignalRateHz;
    trace.values.resize(n);
    const auto& model = world.organs[static_cast<std::size_t>(o)].model;
    if (t.signal == scene::TraceSignal::kActivation) {
      fill_activation_trace(organ, model, t, trace);
    } else if (model.excitation) {
      fill_computed_ecg_trace(computed_ecg(world, o, clip_s), t, trace);
    } else {
      fill_ecg_trace(organ, model, t, clip_s, trace);
    }
  }
  traces_.push_back(std::move(trace));
  trace_series_.push_back(series);
}

void OverlayPlan::record_volume(int organ, int frame, const Eigen::Matrix3Xd& positions) {
  for (VolumeSeries& s : series_) {
    if (s.organ != organ || frame < 0 || static_cast<std::size_t>(frame) >= s.mL.size()) continue;
    const double v = s.triangles.empty() ? mesh::cavity_volume(s.chamber, positions) : sim::enclosed_volume(positions, s.triangles);
    s.mL[static_cast<std::size_t>(frame)] = 1e6 * v;
  }
}

void OverlayPlan::capture(int frame, const std::vector<const Eigen::Matrix3Xd*>& positions, OverlayFrame& out) const {
  out.frame = frame;
  out.time_s = frame / fps_;
  out.labels.resize(targets_.size());
  out.label_visible.assign(targets_.size(), 1);
  // Each view's camera where it is at this frame's time (orbits and paths move it); screen
  // x and y do not depend on the depth range, so any will do.
  // Fixed storage: capture runs every frame (the schema allows at most 16 views).
  std::array<Eigen::Matrix4d, 16> view_projection;
  for (std::size_t v = 0; v < views_.size(); ++v) {
    const scene::Camera camera = camera_at(views_[v].camera, out.time_s);
    view_projection[v] = render::perspective(camera.fov_rad, double(views_[v].rect.width) / views_[v].rect.height,
                                             render::DepthRange{}) *
                         render::look_at(camera);
  }
  int view = 0;
  const auto project = [&](const Eigen::Vector3d& p, double& x, double& y) {
    const Eigen::Vector4d c = view_projection[static_cast<std::size_t>(view)] * p.homogeneous();
    if (c.w() <= 1e-9) return false;
    const scene::PixelRect& r = views_[static_cast<std::size_t>(view)].rect;
    x = r.x + 0.5 * (c.x() / c.w() + 1.0) * r.width;
    y = r.y + 0.5 * (1.0 - c.y() / c.w()) * r.height;
    return true;
  };
  int centre_organ = -1;
  double cx = 0, cy = 0;
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    const LabelTarget& t = targets_[i];
    const Eigen::Matrix3Xd& x = *positions[static_cast<std::size_t>(t.organ)];
    view = t.view;
    if (t.organ != centre_organ) {  // Targets of one organ are consecutive.
      centre_organ = t.organ;
      if (!project(x.rowwise().mean(), cx, cy)) cx = 0.5 * width_, cy = 0.5 * height_;
    }
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int v : t.vertices) sum += x.col(v);
    auto& l = out.labels[i];
    out.label_visible[i] = project(sum / double(t.vertices.size()), l.anchor_x, l.anchor_y);
    l.center_x = cx;
    l.center_y = cy;
  }
}

void OverlayPlan::layout(int width, int height) {
  laid_out_ = true;
  const overlay::Rect frame{0, 0, width, height};
  const int margin = overlay::scaled_px(12, height);
  if (!spec_.title.empty()) {
    font_->size(overlay::scaled_px(spec_.title_size_px, height));
    const int w = static_cast<int>(std::ceil(font_->width(spec_.title)));
    const int h = static_cast<int>(std::ceil(font_->ascent() + font_->descent()));
    title_box_ = {(width - w) / 2, font_->size() / 2, w, h};
  }
  // Each corner stacks its items in the order listed (legend first, then traces), read top
  // to bottom: a bottom corner fills upwards from its last item. Top corners start below the title.
  struct Item {
    scene::Corner corner;
    int width, height;
    overlay::Rect* out;
  };
  std::vector<Item> items;
  if (spec_.legend.enabled && !legend_.empty()) {
    font_->size(overlay::scaled_px(spec_.legend.size_px, height));
    const overlay::Rect size = overlay::legend_size(legend_, *font_);
    items.push_back({spec_.legend.position, size.width, size.height, &legend_box_});
  }
  if (spec_.legend.enabled && !color_bar_.colors.empty()) {
    // The bar: a caption line, then a gradient with tick labels on its right.
    const int w = overlay::scaled_px(150, height), h = overlay::scaled_px(190, height);
    items.push_back({spec_.legend.position, w, h, &legend_box_});
  }
  trace_boxes_.assign(spec_.traces.size(), overlay::Rect{});
  for (std::size_t i = 0; i < spec_.traces.size(); ++i) {
    const auto& t = spec_.traces[i];
    items.push_back({t.position, overlay::scaled_px(t.width_px, height), overlay::scaled_px(t.height_px, height),
                     &trace_boxes_[i]});
  }
  if (spec_.ecg_sheet.enabled) {
    // The paper's own proportions (overlay/ecg_sheet.h: 268 mm x 135 mm), never stretched.
    const int w = overlay::scaled_px(spec_.ecg_sheet.width_px, height);
    items.push_back({spec_.ecg_sheet.position, w, w * 135 / 268, &ecg_sheet_box_});
  }
  const int top_start = spec_.title.empty() ? 0 : title_box_.bottom();
  for (const scene::Corner c : {scene::Corner::kTopLeft, scene::Corner::kTopRight, scene::Corner::kBottomLeft,
                                scene::Corner::kBottomRight}) {
    const bool bottom = c == scene::Corner::kBottomLeft || c == scene::Corner::kBottomRight;
    std::vector<Item*> stack;
    for (Item& item : items)
      if (item.corner == c) stack.push_back(&item);
    if (bottom) std::reverse(stack.begin(), stack.end());
    int used = bottom ? 0 : top_start;
    for (Item* item : stack) {
      overlay::Rect r = overlay::corner_rect(frame, static_cast<overlay::Corner>(c), item->width, item->height, margin);
      r.y += bottom ? -used : used;
      used += item->height + margin / 2;
      *item->out = r;
    }
  }
}

void OverlayPlan::draw(Image& image, const OverlayFrame& frame) {
  if (empty_) return;
  if (!font_) font_ = std::make_unique<plot::Font>();
  if (!laid_out_) layout(image.width, image.height);
  const overlay::Style style;

  if (!targets_.empty()) {
    font_->size(overlay::scaled_px(spec_.labels.size_px, image.height));
    std::vector<overlay::LabelRequest> requests;
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      if (!frame.label_visible[i]) continue;
      requests.push_back(frame.labels[i]);
      requests.back().text = targets_[i].text;
    }
    std::vector<overlay::Rect> keep_out = trace_boxes_;
    if (legend_box_.width > 0) keep_out.push_back(legend_box_);
    if (ecg_sheet_box_.width > 0) keep_out.push_back(ecg_sheet_box_);
    if (title_box_.width > 0) keep_out.push_back(title_box_);
    placed_ = overlay::place_labels(requests, overlay::Rect{0, 0, image.width, image.height}, keep_out, *font_);
    overlay::draw_labels(image, placed_, *font_, style);
  }
  if (legend_box_.width > 0) {
    font_->size(overlay::scaled_px(spec_.legend.size_px, image.height));
    if (color_bar_.colors.empty()) {
      overlay::draw_legend(image, legend_box_, legend_, *font_, style);
    } else {
      overlay::draw_color_bar(image, legend_box_, color_bar_, *font_, style);
    }
  }
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    overlay::Trace& trace = traces_[i];
    if (const int s = trace_series_[i]; s >= 0) {
      // Only what is simulated so far: frames up to this one (later ones may be in the making).
      const auto& history = series_[static_cast<std::size_t>(s)].mL;
      trace.values.assign(history.begin(), history.begin() + std::min<std::ptrdiff_t>(frame.frame + 1, history.size()));
      trace.known_until_s = frame.time_s;
    }
    font_->size(overlay::scaled_px(13, image.height));
    overlay::draw_trace(image, trace_boxes_[i], trace, frame.time_s, *font_, style);
  }
  if (ecg_sheet_box_.width > 0) overlay::draw_ecg_sheet(image, ecg_sheet_box_, ecg_sheet_, *font_, frame.time_s, frame.time_s);
  if (!spec_.title.empty()) {
    overlay::draw_title(image, overlay::Rect{0, 0, image.width, image.height}, spec_.title, *font_,
                        overlay::scaled_px(spec_.title_size_px, image.height), style);
  }
  for (const ViewFrame& v : views_) {
    if (v.title.empty()) continue;
    overlay::draw_title(image, overlay::Rect{v.rect.x, v.rect.y, v.rect.width, v.rect.height}, v.title, *font_,
                        overlay::scaled_px(spec_.title_size_px, image.height), style);
  }
}

}  // namespace systole::clip
