#pragma once
// The scene's teaching overlays (scene::Overlay) on a clip's frames: what to label, list
// and trace, worked out once per clip; the label anchors captured from each frame's
// positions where the simulation hands them on; everything drawn on the finished
// (anti-aliased) frame so text stays crisp. src/overlay/ does the drawing.

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/image.h"
#include "electro/ecg.h"
#include "mesh/anatomy.h"
#include "overlay/ecg_sheet.h"
#include "overlay/labels.h"
#include "overlay/legend.h"
#include "overlay/trace.h"
#include "scene/scene.h"
#include "world/world.h"

namespace systole::clip {

/// What the overlay needs of one frame, captured beside the positions.
struct OverlayFrame {
  int frame = 0;
  double time_s = 0;                                  ///< unit: s
  std::vector<overlay::LabelRequest> labels;          ///< In the plan's label order; texts filled in by draw.
  std::vector<char> label_visible;                    ///< False: the anchor is behind the camera.
};

class OverlayPlan {
 public:
  /// Resolves the scene's overlay against the built world. Volume traces make the world
  /// record the organ's enclosed volume, or a chamber's, at every frame it advances
  /// (record_volume). A chamber the organ's anatomy lacks is an error naming the trace.
  OverlayPlan(const scene::Scene& scene, const world::World& world);
  OverlayPlan(const OverlayPlan&) = delete;
  OverlayPlan& operator=(const OverlayPlan&) = delete;
  ~OverlayPlan();

  bool empty() const { return empty_; }
  /// Organs whose volume is traced (their index in the world).
  const std::vector<int>& volume_organs() const { return volume_organs_; }
  /// Records organ `organ`'s traced volumes at `frame` from its render-mesh positions. unit: m
  void record_volume(int organ, int frame, const Eigen::Matrix3Xd& positions);

  /// The label anchors of `frame` from every organ's render-mesh positions. unit: m
  void capture(int frame, const std::vector<const Eigen::Matrix3Xd*>& positions, OverlayFrame& out) const;
  /// Draws everything on `image` (the frame's size). Not thread-safe: one drawing thread.
  void draw(Image& image, const OverlayFrame& frame);

  /// Where the labels of the last draw went (for tests). unit: px
  const std::vector<overlay::PlacedLabel>& placed_labels() const { return placed_; }
  /// Where each trace inset of the last draw went (for tests). unit: px
  const std::vector<overlay::Rect>& trace_boxes() const { return trace_boxes_; }
  /// The traces as of the last draw.
  const std::vector<overlay::Trace>& traces() const { return traces_; }
  /// Where the legend of the last draw went (empty rect: none). unit: px
  const overlay::Rect& legend_box() const { return legend_box_; }
  /// Where the ECG sheet of the last draw went (empty rect: none). unit: px
  const overlay::Rect& ecg_sheet_box() const { return ecg_sheet_box_; }
  const std::vector<overlay::LegendEntry>& legend_entries() const { return legend_; }

 private:
  struct LabelTarget {
    int organ = 0;
    int view = 0;               ///< The view it is labelled in (overlay.labels.view, else the first that shows its organ).
    std::string text;
    std::vector<int> vertices;  ///< Render-mesh vertices of the region that the view's cut keeps.
  };
  /// A view of the frame (the whole frame when the scene has no `views`).
  struct ViewFrame {
    scene::Camera camera;       ///< As written; moved to each frame's time by camera_at.
    scene::PixelRect rect;      ///< unit: px
    std::string title;
  };
  // The constructor's parts, in order: views first (they decide whether anything is drawn).
  void plan_views(const scene::Scene& scene);
  void plan_labels(const scene::Scene& scene, const world::World& world);
  void plan_legend(const scene::Scene& scene, const world::World& world);
  void plan_trace(const scene::Scene& scene, const world::World& world, const scene::TraceOverlay& t, int index);
  void plan_ecg_sheet(const scene::Scene& scene, const world::World& world);
  /// The organ's computed ECG over the clip, computed once for every trace and the sheet.
  const electro::Ecg& computed_ecg(const world::World& world, int organ, double clip_s);
  void layout(int width, int height);

  bool empty_ = true;
  scene::Overlay spec_;
  std::vector<ViewFrame> views_;
  overlay::ColorBar color_bar_;  ///< The legend organ's scalar colour map (strain, activation); empty colors: none.
  int width_ = 0, height_ = 0;  ///< unit: px
  double fps_ = 30;
  std::vector<LabelTarget> targets_;
  std::vector<overlay::LegendEntry> legend_;
  std::vector<overlay::Trace> traces_;
  /// A traced volume: the closed render mesh of an organ, or one chamber of its anatomy.
  struct VolumeSeries {
    int organ = 0;
    std::vector<Eigen::Vector3i> triangles;  ///< The whole surface's; empty when a chamber.
    mesh::Cavity chamber;                    ///< Its lining and rims, when a chamber.
    std::vector<double> mL;                  ///< Per frame, NaN until recorded. unit: mL
  };
  std::vector<int> trace_series_;  ///< Per trace: the volume series it shows, or -1.
  std::map<int, electro::Ecg> ecgs_;  ///< Per organ with a conduction system shown: its ECG over the clip.
  overlay::EcgSheet ecg_sheet_;     ///< The organ's 12 leads over the clip, when overlay.ecg_sheet is on.
  std::vector<int> volume_organs_;
  std::vector<VolumeSeries> series_;

  std::unique_ptr<plot::Font> font_;  ///< Loaded on the drawing thread's first frame.
  bool laid_out_ = false;
  overlay::Rect legend_box_, title_box_, ecg_sheet_box_;
  std::vector<overlay::Rect> trace_boxes_;
  std::vector<overlay::PlacedLabel> placed_;
};

}  // namespace systole::clip
