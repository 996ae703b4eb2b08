// Overlays on a simulated heart (scenes/heart-labels.yaml, small): each label's leader ends
// inside its region's projected bounds and its text is on screen; labels follow their
// regions as they move; the volume trace falls as the ventricles contract; the cursor moves
// with the frame time; the legend lists each region colour; a whole render is the same
// bits with and without overlapping stages.

#include "clip/overlay_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "clip/bake.h"
#include "world/frame_source.h"
#include "clip/camera_framing.h"
#include "clip/progress.h"
#include "clip/render_clip.h"
#include "common/error.h"
#include "render/camera_matrices.h"
#include "render/color_map.h"
#include "scene/load.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::test {
namespace {

constexpr int kWidth = 640, kHeight = 360;

scene::Scene labelled_heart() {
  return scene::load(source("scenes/heart-labels.yaml"),
                     {"output.width=" + std::to_string(kWidth), "output.height=" + std::to_string(kHeight)});
}

/// Every organ's render-mesh positions now. unit: m
std::vector<Eigen::Matrix3Xd> positions_now(const world::World& world) {
  std::vector<Eigen::Matrix3Xd> out(world.organs.size());
  for (std::size_t o = 0; o < world.organs.size(); ++o) world::render_positions(world.organs[o], out[o]);
  return out;
}

clip::OverlayFrame capture(const clip::OverlayPlan& plan, int frame, const std::vector<Eigen::Matrix3Xd>& x) {
  std::vector<const Eigen::Matrix3Xd*> p;
  for (const auto& m : x) p.push_back(&m);
  clip::OverlayFrame f;
  plan.capture(frame, p, f);
  return f;
}

/// The screen bounding box of a region's vertices, projected independently of the plan.
overlay::Rect projected_bounds(const scene::Scene& s, const Eigen::Matrix3Xd& x, const std::vector<int>& vertex_region,
                               int region) {
  const Eigen::Matrix4d m = render::perspective(s.camera.fov_rad, double(kWidth) / kHeight, {}) * render::look_at(s.camera);
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    if (vertex_region[static_cast<std::size_t>(v)] != region) continue;
    const Eigen::Vector4d c = m * x.col(v).homogeneous();
    const double px = 0.5 * (c.x() / c.w() + 1) * kWidth, py = 0.5 * (1 - c.y() / c.w()) * kHeight;
    x0 = std::min(x0, px), y0 = std::min(y0, py), x1 = std::max(x1, px), y1 = std::max(y1, py);
  }
  return {int(std::floor(x0)), int(std::floor(y0)), int(std::ceil(x1 - x0)) + 1, int(std::ceil(y1 - y0)) + 1};
}

int region_of(const scene::Organ& organ, const std::string& label) {
  for (std::size_t r = 0; r < organ.regions.size(); ++r) {
    std::string name = organ.regions[r].name;
    std::replace(name.begin(), name.end(), '_', ' ');
    if (name == label) return static_cast<int>(r);
  }
  return -1;
}

int differing_pixels(const Image& a, const Image& b, const overlay::Rect& r) {
  int n = 0;
  for (int y = std::max(0, r.y); y < std::min(r.bottom(), a.height); ++y)
    for (int x = std::max(0, r.x); x < std::min(r.right(), a.width); ++x)
      n += !std::equal(a.pixel(x, y), a.pixel(x, y) + 3, b.pixel(x, y));
  return n;
}

TEST(OverlayPlan, LabelsLandOnTheirRegionsAndFollowThem) {
  const scene::Scene s = labelled_heart();
  world::World world = world::build_world(s);
  clip::OverlayPlan plan(s, world);
  const auto& organ = s.organs[0];
  const auto& vertex_region = world.organs[0].geometry.vertex_region;

  std::vector<std::pair<double, double>> anchors_at_rest;
  for (int frame : {0, 10}) {  // Rest, and mid ventricular contraction (t = 0.33 s).
    world::advance_to_frame(world, frame);
    const auto x = positions_now(world);
    const clip::OverlayFrame f = capture(plan, frame, x);
    Image image(kWidth, kHeight);
    const Image before = image;
    plan.draw(image, f);
    const auto& placed = plan.placed_labels();
    ASSERT_EQ(placed.size(), s.overlay.labels.regions.size());
    std::vector<std::pair<double, double>> anchors;
    for (const auto& l : placed) {
      const int r = region_of(organ, l.text);
      ASSERT_GE(r, 0) << l.text;
      const overlay::Rect bounds = projected_bounds(s, x[0], vertex_region, r);
      EXPECT_TRUE(bounds.contains(l.anchor_x, l.anchor_y))
          << l.text << " anchor " << l.anchor_x << "," << l.anchor_y << " bounds " << bounds.x << "," << bounds.y << " "
          << bounds.width << "x" << bounds.height;
      // The text is on screen, and drawn there.
      EXPECT_GE(l.box.x, 0);
      EXPECT_GE(l.box.y, 0);
      EXPECT_LE(l.box.right(), kWidth);
      EXPECT_LE(l.box.bottom(), kHeight);
      EXPECT_GT(differing_pixels(image, before, l.box), 30) << l.text;
      anchors.emplace_back(l.anchor_x, l.anchor_y);
    }
    if (frame == 0) {
      anchors_at_rest = anchors;
      continue;
    }
    // The contracting ventricles move their labels' anchors.
    double moved = 0;
    for (std::size_t i = 0; i < anchors.size(); ++i)
      moved = std::max(moved, std::hypot(anchors[i].first - anchors_at_rest[i].first, anchors[i].second - anchors_at_rest[i].second));
    EXPECT_GT(moved, 0.5);
  }
}

TEST(OverlayPlan, LabelsInACutViewNameWhatTheCutKeeps) {
  // heart-cutaway's second view cut across the short axis instead: the apical half is cut
  // away, so the apex has nothing left to label while the left ventricle's lining does, and
  // every label lands in that view (the right half of the frame).
  const scene::Scene given = scene::load(
      source("scenes/heart-cutaway.yaml"),
      {"output.width=" + std::to_string(kWidth), "output.height=" + std::to_string(kHeight),
       "views.1.clip.section=short_axis", "overlay.labels.regions=[apex, left_ventricle_cavity, mitral_valve]"});
  world::World world = world::build_world(given);
  const scene::Scene s = clip::with_cameras_placed(given, world);
  clip::OverlayPlan plan(s, world);
  const clip::OverlayFrame f = capture(plan, 0, positions_now(world));
  Image image(kWidth, kHeight);
  plan.draw(image, f);
  std::vector<std::string> texts;
  for (const auto& l : plan.placed_labels()) {
    texts.push_back(l.text);
    EXPECT_GE(l.anchor_x, kWidth / 2) << l.text;  // In the cut view.
  }
  EXPECT_EQ(texts, (std::vector<std::string>{"left ventricle cavity", "mitral valve"}));
}

TEST(OverlayPlan, VolumeTraceFallsAsTheVentriclesContractAndTheCursorMoves) {
  const scene::Scene s = labelled_heart();
  world::FrameSource source(s);
  const world::World& world = source.world();
  clip::OverlayPlan plan(s, world);
  ASSERT_EQ(plan.volume_organs(), std::vector<int>{0});
  Eigen::Matrix3Xd x;
  source.on_frame([&](int frame) {
    source.positions(0, x);
    plan.record_volume(0, frame, x);
  });
  std::size_t volume = 0;
  while (s.overlay.traces[volume].signal != scene::TraceSignal::kVolume) ++volume;

  double previous_cursor = -1;
  const int ecg = volume == 0 ? 1 : 0;
  std::vector<double> values;
  for (int frame : {4, 10, 20}) {
    source.advance_to(frame);
    const auto p = positions_now(world);
    Image image(kWidth, kHeight);
    plan.draw(image, capture(plan, frame, p));
    const overlay::Trace& trace = plan.traces()[volume];
    values = trace.values;
    ASSERT_EQ(values.size(), static_cast<std::size_t>(frame + 1));
    // The cursor moves right with the frame time (the window is 3 s: no wrap yet).
    plot::Font font;
    font.size(overlay::scaled_px(13, kHeight));
    const overlay::Rect area = overlay::trace_plot_area(plan.trace_boxes()[ecg], font);
    const double cursor = overlay::cursor_x(area, plan.traces()[ecg], frame / s.output.fps);
    EXPECT_GT(cursor, previous_cursor);
    previous_cursor = cursor;
    // ... and is drawn: a light vertical line there.
    int light = 0;
    for (int y = area.y; y < area.bottom(); ++y) {
      int brightest = 0;  // The line may fall between two columns.
      for (int x = int(cursor) - 1; x <= int(cursor) + 1; ++x) brightest = std::max<int>(brightest, image.pixel(x, y)[0]);
      light += brightest > 120;
    }
    EXPECT_GT(light, area.height / 2) << frame;
  }
  // Frames 0-4: atrial systole only (t < 0.16 s). Frames 5-14: ventricular systole. Volume
  // at its lowest in ventricular systole, below the rest and below diastole's refill.
  const auto lowest = std::min_element(values.begin(), values.end()) - values.begin();
  EXPECT_GE(lowest, 6);
  EXPECT_LE(lowest, 15);
  EXPECT_LT(values[static_cast<std::size_t>(lowest)], values[0] * (1 - 0.005));
  EXPECT_GT(values[20], values[static_cast<std::size_t>(lowest)]);
  // The trace is the left ventricle's blood, not the heart's: 116 ml at end-diastole
  // (docs/anatomy.md), where the whole surface encloses several times that.
  EXPECT_EQ(plan.traces()[volume].title, "volume: left ventricle");
  EXPECT_GT(values[0], 100);
  EXPECT_LT(values[0], 130);
  EXPECT_LT(values[static_cast<std::size_t>(lowest)], 0.7 * values[0]) << "the ventricle ejects";
}

// The 12-lead sheet (overlay.ecg_sheet, scenes/heart-conduction.yaml): in its corner at the
// paper's proportions, and written as an ECG machine writes: the second column (2.5-5 s),
// right of its lead names, is blank paper at 1 s and carries its three leads at 4.5 s.
TEST(OverlayPlan, TheEcgSheetIsWrittenUpToTheFramesTime) {
  const scene::Scene s = scene::load(source("scenes/heart-conduction.yaml"));  // 1280x720: the sheet 440 px wide.
  ASSERT_TRUE(s.overlay.ecg_sheet.enabled);
  world::World world = world::build_world(s);
  clip::OverlayPlan plan(s, world);
  const auto p = positions_now(world);
  const auto ink_in_second_column = [&](int frame) {
    Image image(s.output.width, s.output.height);
    plan.draw(image, capture(plan, frame, p));
    const overlay::EcgSheetLayout layout = overlay::ecg_sheet_layout(plan.ecg_sheet_box());
    int ink = 0;  // The trace is near black; the paper and its grid are light and pink.
    for (int y = int(layout.row_top(0)); y < int(layout.row_top(3)); ++y) {
      for (int x = int(layout.x_at(3.5)); x < int(layout.x_at(5.0)) - 2; ++x) {  // Right of the lead names.
        const auto px = image.pixel(x, y);
        ink += px[0] < 90 && px[1] < 90 && px[2] < 90;
      }
    }
    return ink;
  };
  EXPECT_EQ(ink_in_second_column(30), 0) << "nothing after 1 s is written at 1 s";
  EXPECT_GT(ink_in_second_column(135), 100) << "3.5-4.5 s of three leads at 4.5 s";
  const overlay::Rect box = plan.ecg_sheet_box();
  EXPECT_EQ(box.x, overlay::scaled_px(12, s.output.height)) << "bottom-left";
  EXPECT_EQ(box.bottom(), s.output.height - overlay::scaled_px(12, s.output.height));
  EXPECT_NEAR(double(box.width) / box.height, 268.0 / 135, 0.02);
}

// A sheet needs twelve leads: an organ without a conduction system is refused.
TEST(OverlayPlan, AnEcgSheetNeedsElectrophysiology) {
  try {
    scene::load(source("scenes/heart-labels.yaml"), {"overlay.ecg_sheet.width=400"});
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("overlay.ecg_sheet"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("electrophysiology"), std::string::npos) << e.what();
  }
}

TEST(OverlayPlan, AChamberTheMeshLacksIsAnErrorNamingTheTraceAndTheChambers) {
  const std::vector<std::string> size = {"output.width=" + std::to_string(kWidth), "output.height=" + std::to_string(kHeight)};
  auto message = [](const scene::Scene& s) {
    const world::World world = world::build_world(s);
    try {
      clip::OverlayPlan plan(s, world);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::vector<std::string> typo = size;
  typo.push_back("overlay.traces.1.chamber=left_ventricel");
  const std::string wrong = message(scene::load(source("scenes/heart-labels.yaml"), typo));
  EXPECT_NE(wrong.find("heart-labels.yaml:"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("overlay.traces[1].chamber"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("chambers: left_ventricle, left_atrium, right_ventricle, right_atrium"), std::string::npos)
      << wrong;
  std::vector<std::string> kidney = size;  // A generated surface without an anatomy.
  kidney.push_back("overlay.traces=[{signal: volume, chamber: left_ventricle}]");
  const std::string none = message(scene::load(source("scenes/kidney.yaml"), kidney));
  EXPECT_NE(none.find("no generated anatomy"), std::string::npos) << none;
}

TEST(OverlayPlan, LegendListsEachRegionColour) {
  const scene::Scene s = labelled_heart();
  const world::World world = world::build_world(s);
  clip::OverlayPlan plan(s, world);
  const auto x = positions_now(world);
  Image image(kWidth, kHeight);
  plan.draw(image, capture(plan, 0, x));
  const auto& entries = plan.legend_entries();
  // The scene colours by region: each swatch is the colour the renderer paints its region
  // with (the region's own colour, else the palette's).
  const auto painted = render::region_legend(s.organs[0]);
  ASSERT_EQ(entries.size(), s.organs[0].regions.size());  // Every region coloured: no body entry.
  ASSERT_EQ(painted.size(), entries.size());
  plot::Font font;
  font.size(overlay::scaled_px(s.overlay.legend.size_px, kHeight));
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& c = painted[i].color;
    double sx = 0, sy = 0;
    overlay::swatch_center(plan.legend_box(), static_cast<int>(i), font, sx, sy);
    const std::uint8_t* p = image.pixel(int(sx), int(sy));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], std::lround(c[k] * 255)) << entries[i].name;
  }
}

TEST(OverlayPlan, LabelsDoNotHopFromFrameToFrameInTheShippedScene) {
  // Placement is decided afresh every frame; for a beating heart the labels should still
  // glide with their regions, never jump to another side.
  const scene::Scene s = labelled_heart();
  world::World world = world::build_world(s);
  clip::OverlayPlan plan(s, world);
  std::vector<overlay::PlacedLabel> previous;
  double largest = 0;
  for (int frame = 0; frame < 75; ++frame) {  // 2.5 s: three beats.
    world::advance_to_frame(world, frame);
    const auto x = positions_now(world);
    Image image(kWidth, kHeight);
    plan.draw(image, capture(plan, frame, x));
    const auto& placed = plan.placed_labels();
    for (std::size_t i = 0; i < previous.size(); ++i) {
      EXPECT_TRUE(placed[i].free) << placed[i].text << " at frame " << frame;
      // Where the box sits relative to its anchor: steady when the label glides along.
      const double dx = (placed[i].box.x - placed[i].anchor_x) - (previous[i].box.x - previous[i].anchor_x);
      const double dy = (placed[i].box.y - placed[i].anchor_y) - (previous[i].box.y - previous[i].anchor_y);
      largest = std::max(largest, std::hypot(dx, dy));
    }
    previous = placed;
  }
  EXPECT_LT(largest, 4.0) << "a label jumped";
}

TEST(OverlayPlan, FramesAreTheSameBitsOverlappedSerialSelectedAndBaked) {
  namespace fs = std::filesystem;
  const auto dir = scratch("overlay_bits");
  const auto s = scene::load(source("scenes/heart-labels.yaml"),
                             {"output.width=320", "output.height=240", "output.duration=1 s"});
  clip::bake_clip(s, dir / "clip.bake", clip::ProgressStyle::kNone, "test");
  const std::vector<std::pair<std::string, std::vector<int>>> runs = {
      {"overlap", {}}, {"serial", {}}, {"selected", {12, 25}}, {"baked", {12, 25}}};
  for (const auto& [name, frames] : runs) {
    clip::RenderRequest request;
    request.png_dir = dir / name;
    request.overlap = name != "serial";
    request.frames = frames;
    if (name == "baked") request.from_bake = dir / "clip.bake";
    clip::render_clip(s, request);
  }
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir / "serial")) {
    const auto name = entry.path().filename();
    EXPECT_EQ(read_file(dir / "overlap" / name), read_file(entry.path())) << name << " differs";
    if (fs::exists(dir / "selected" / name)) {
      // The volume trace of a selected frame holds the frames stepped through unrendered.
      EXPECT_EQ(read_file(dir / "selected" / name), read_file(entry.path())) << name << " differs when selected";
      // From a bake, the volume history is read from the bake's frames.
      EXPECT_EQ(read_file(dir / "baked" / name), read_file(entry.path())) << name << " differs from a bake";
      ++compared;
    }
  }
  EXPECT_EQ(compared, 2);
}

}  // namespace
}  // namespace systole::test
