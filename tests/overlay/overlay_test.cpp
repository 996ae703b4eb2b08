// Teaching overlays, drawn on plain images: labels end their leader at the anchor, keep
// clear of each other and of insets, and show their text; the halo keeps text readable on
// dark and light alike; legend swatches and the colour bar show exactly their colours; the
// trace cursor moves with time and the sweep wraps; the ECG marks each beat; titles sit
// centred on top; the same calls give the same bytes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "overlay/labels.h"
#include "overlay/legend.h"
#include "overlay/title.h"
#include "overlay/trace.h"

namespace systole::overlay {
namespace {

Image filled(int w, int h, std::uint8_t v) {
  Image image(w, h);
  std::fill(image.rgb.begin(), image.rgb.end(), v);
  return image;
}

double luma(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/// Pixels inside `r` that differ from `background`.
int changed_pixels(const Image& image, const Rect& r, std::uint8_t background) {
  int n = 0;
  for (int y = std::max(r.y, 0); y < std::min(r.bottom(), image.height); ++y) {
    for (int x = std::max(r.x, 0); x < std::min(r.right(), image.width); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n += p[0] != background || p[1] != background || p[2] != background;
    }
  }
  return n;
}

TEST(Labels, LeaderEndsAtTheAnchorAndTextIsDrawnInItsBox) {
  plot::Font font;
  font.size(16);
  const Rect frame{0, 0, 640, 360};
  const std::vector<LabelRequest> requests = {{"left ventricle", 380, 220, 320, 180}};
  const auto placed = place_labels(requests, frame, {}, font);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_TRUE(placed[0].free);
  EXPECT_DOUBLE_EQ(placed[0].anchor_x, 380);
  EXPECT_DOUBLE_EQ(placed[0].anchor_y, 220);
  // Outward from the centre (down and right of it): the box lies down and to the right.
  EXPECT_GT(placed[0].box.x, 380);
  EXPECT_GT(placed[0].box.bottom(), 220);
  Image image = filled(640, 360, 128);
  draw_labels(image, placed, font);
  EXPECT_GT(changed_pixels(image, placed[0].box, 128), 100);
  // The anchor dot is drawn in ink.
  EXPECT_GT(luma(image, 380, 220), 200);
}

TEST(Labels, DoNotOverlapEachOtherTheEdgeOrInsets) {
  plot::Font font;
  font.size(16);
  const Rect frame{0, 0, 640, 360};
  // Five regions crowded together near the right edge, an inset in the bottom right.
  std::vector<LabelRequest> requests;
  for (int i = 0; i < 5; ++i) requests.push_back({"region " + std::to_string(i), 560.0 + 4 * i, 150.0 + 8 * i, 320, 180});
  const std::vector<Rect> insets = {{440, 250, 190, 100}};
  const auto placed = place_labels(requests, frame, insets, font);
  ASSERT_EQ(placed.size(), requests.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_TRUE(placed[i].free) << i;
    EXPECT_GE(placed[i].box.x, 0);
    EXPECT_GE(placed[i].box.y, 0);
    EXPECT_LE(placed[i].box.right(), frame.width);
    EXPECT_LE(placed[i].box.bottom(), frame.height);
    EXPECT_FALSE(placed[i].box.overlaps(insets[0])) << i;
    for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(placed[i].box.overlaps(placed[j].box)) << i << " " << j;
  }
}

/// Percentile spread of luminance inside a box: how far apart ink and its surround are.
double contrast(const Image& image, const Rect& r) {
  std::vector<double> l;
  for (int y = r.y; y < r.bottom(); ++y)
    for (int x = r.x; x < r.right(); ++x) l.push_back(luma(image, x, y));
  std::sort(l.begin(), l.end());
  return l[l.size() * 97 / 100] - l[l.size() * 3 / 100];
}

TEST(Text, HaloKeepsTextReadableOnDarkAndLightBackgrounds) {
  plot::Font font;
  font.size(18);
  const Style style;
  const Rect box{8, 8, 200, 30};
  for (std::uint8_t background : {std::uint8_t{0}, std::uint8_t{128}, std::uint8_t{255}}) {
    Image image = filled(220, 46, background);
    plot::Canvas canvas(image);
    font.draw_with_halo(canvas, "right atrium", 12, 30, style.ink, style.halo, 3, style.halo_alpha);
    EXPECT_GT(contrast(image, box), 150) << "background " << int(background);
  }
  // Without the halo, light text on a light background is not readable: the control.
  Image bare = filled(220, 46, 250);
  plot::Canvas canvas(bare);
  font.draw(canvas, "right atrium", 12, 30, style.ink);
  EXPECT_LT(contrast(bare, box), 30);
}

TEST(Legend, ShowsEachRegionsColourInItsSwatch) {
  plot::Font font;
  font.size(14);
  const std::vector<LegendEntry> entries = {{"aorta", {201, 96, 90}}, {"pulmonary trunk", {122, 111, 176}},
                                            {"vena cava", {90, 111, 184}}};
  Rect box = legend_size(entries, font);
  box.x = 20;
  box.y = 30;
  for (std::uint8_t background : {std::uint8_t{0}, std::uint8_t{255}}) {
    Image image = filled(300, 200, background);
    draw_legend(image, box, entries, font);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      double x = 0, y = 0;
      swatch_center(box, static_cast<int>(i), font, x, y);
      const std::uint8_t* p = image.pixel(static_cast<int>(x), static_cast<int>(y));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], entries[i].color[k]) << entries[i].name;
      // The name is written to the right of the swatch.
      EXPECT_GT(changed_pixels(image, Rect{int(x) + font.size(), int(y) - 8, box.right() - int(x) - font.size(), 16}, 0), 10);
    }
  }
}

TEST(ColorBar, ShowsTheMapFromMinAtTheBottomToMaxAtTheTop) {
  plot::Font font;
  font.size(13);
  const ColorBar bar{"strain", "%", -10, 10, {{0, 0, 255}, {255, 255, 255}, {255, 0, 0}}};
  EXPECT_EQ(color_at(bar, -10), (Rgb{0, 0, 255}));
  EXPECT_EQ(color_at(bar, 0), (Rgb{255, 255, 255}));
  EXPECT_EQ(color_at(bar, 5), (Rgb{255, 128, 128}));
  EXPECT_EQ(color_at(bar, 99), (Rgb{255, 0, 0}));  // Clamped.
  Image image = filled(200, 260, 40);
  Rect gradient;
  draw_color_bar(image, Rect{10, 10, 120, 240}, bar, font, {}, &gradient);
  ASSERT_GT(gradient.height, 100);
  const int cx = gradient.x + gradient.width / 2;
  const std::uint8_t* bottom = image.pixel(cx, gradient.bottom() - 1);
  const std::uint8_t* top = image.pixel(cx, gradient.y);
  EXPECT_EQ((Rgb{bottom[0], bottom[1], bottom[2]}), (Rgb{0, 0, 255}));
  EXPECT_EQ((Rgb{top[0], top[1], top[2]}), (Rgb{255, 0, 0}));
  const std::uint8_t* mid = image.pixel(cx, gradient.y + (gradient.height - 1) / 2);
  EXPECT_GT(mid[1], 230);  // White in the middle (0 %).
  // The tick labels (-10, 0, 10) are written right of the bar.
  EXPECT_GT(changed_pixels(image, Rect{gradient.right() + 6, gradient.y, 60, gradient.height}, 40), 30);
}

Trace sine_trace(double window_s) {
  Trace t;
  t.title = "test";
  t.clip_s = 10;
  t.window_s = window_s;
  t.sample_dt_s = 0.01;
  for (int i = 0; i <= 1000; ++i) t.values.push_back(std::sin(i * 0.01 * 6.283));
  return t;
}

TEST(Trace, CursorMovesWithTimeAndTheSweepWraps) {
  const Trace t = sine_trace(3);
  const Rect plot{100, 50, 300, 80};
  EXPECT_LT(cursor_x(plot, t, 1.0), cursor_x(plot, t, 2.0));
  EXPECT_NEAR(cursor_x(plot, t, 1.5), 150 + 100, 1e-9);
  // A new sweep starts at the left.
  EXPECT_NEAR(cursor_x(plot, t, 3.3), 100 + 30, 1e-9);
  // The whole clip: the cursor crosses it once.
  const Trace whole = sine_trace(0);
  EXPECT_NEAR(cursor_x(plot, whole, 5.0), 250, 1e-9);
  EXPECT_NEAR(cursor_x(plot, whole, 10.0), 400, 1e-9);
}

/// Columns of the plot area where the (green) curve shows, full or dimmed.
std::vector<int> curve_columns(const Image& image, const Rect& plot) {
  std::vector<int> cols;
  for (int x = plot.x; x < plot.right(); ++x) {
    for (int y = plot.y; y < plot.bottom(); ++y) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[1] - p[0] > 20 && p[1] - p[2] > 20) {
        cols.push_back(x);
        break;
      }
    }
  }
  return cols;
}

TEST(Trace, DrawnCursorMovesAndASimulatedSignalStopsAtIt) {
  plot::Font font;
  font.size(12);
  Trace t = sine_trace(0);  // Whole clip.
  const Rect box{10, 10, 320, 100};
  const Rect plot = trace_plot_area(box, font);
  double previous = -1;
  for (double now : {2.0, 4.0, 7.0}) {
    t.known_until_s = now;  // Known only as simulated.
    Image image = filled(340, 120, 255);
    draw_trace(image, box, t, now, font);
    const auto cols = curve_columns(image, plot);
    ASSERT_FALSE(cols.empty());
    // The curve reaches the cursor and not beyond it.
    const double cursor = cursor_x(plot, t, now);
    EXPECT_NEAR(cols.back(), cursor, 4) << now;
    EXPECT_GT(cursor, previous);
    previous = cursor;
  }
  // A signal known in advance is drawn over the whole width, ahead of the cursor dimmed.
  t.known_until_s = std::numeric_limits<double>::infinity();
  Image image = filled(340, 120, 255);
  draw_trace(image, box, t, 4.0, font);
  const int drawn = static_cast<int>(curve_columns(image, plot).size());
  EXPECT_GT(drawn, plot.width * 9 / 10);
}

TEST(Trace, SamplesBetweenAndOnlyWhereKnown) {
  Trace t;
  t.sample_dt_s = 0.5;
  t.values = {0, 1, 2};
  EXPECT_DOUBLE_EQ(sample(t, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(sample(t, 1.0), 2.0);
  EXPECT_TRUE(std::isnan(sample(t, 1.2)));
  t.known_until_s = 0.5;
  EXPECT_DOUBLE_EQ(sample(t, 0.5), 1.0);
  EXPECT_TRUE(std::isnan(sample(t, 0.6)));
}

TEST(Ecg, MarksEachBeatWithAnRPeakAfterItsPWave) {
  const std::vector<double> r = {0.5, 1.3, 1.9};  // Irregular RR.
  for (double at : r) {
    EXPECT_NEAR(ecg_value(at, r), 1.0, 0.05);
    EXPECT_LT(ecg_value(at + 0.03, r), 0);  // S.
    EXPECT_GT(ecg_value(at - 0.16, r), 0.1);  // P.
    EXPECT_LT(std::abs(ecg_value(at - 0.08, r)), 0.05);  // PR segment: back at the baseline.
  }
  EXPECT_NEAR(ecg_value(0.0, r), 0.0, 0.02);
}

TEST(Ecg, PWavesComeFromTheAtriaWhenGivenAndVanishInFibrillation) {
  const std::vector<double> r = {0.5, 1.3};
  const std::vector<double> p = {0.25, 1.05};  // A PR of 250 ms: first-degree block.
  EXPECT_NEAR(ecg_value(0.25, r, &p), 0.15, 0.02);
  EXPECT_LT(std::abs(ecg_value(0.34, r, &p)), 0.02);  // None at the default 160 ms.
  const std::vector<double> none;
  for (double at : r) {
    EXPECT_NEAR(ecg_value(at, r, &none), 1.0, 0.05);
    EXPECT_LT(std::abs(ecg_value(at - 0.16, r, &none)), 0.01);
  }
}

TEST(Title, IsCentredOnTopOfItsRect) {
  plot::Font font;
  Image image = filled(640, 360, 255);
  const Rect view{320, 0, 320, 360};  // The right half, as one view of a split screen.
  const Rect box = draw_title(image, view, "fibrillation", font);
  EXPECT_NEAR(box.x + box.width / 2.0, 480, 2);
  EXPECT_LT(box.bottom(), 60);
  EXPECT_GT(changed_pixels(image, box, 255), 100);
  EXPECT_EQ(changed_pixels(image, Rect{0, 0, 320, 360}, 255), 0);  // The left view untouched.
}

TEST(Overlay, SameCallsGiveTheSameBytes) {
  auto draw = [] {
    plot::Font font;
    Image image = filled(320, 240, 60);
    font.size(12);
    const auto placed = place_labels({{"apex", 150, 170, 160, 120}, {"aorta", 160, 60, 160, 120}}, {0, 0, 320, 240}, {}, font);
    draw_labels(image, placed, font);
    draw_trace(image, {180, 150, 130, 80}, sine_trace(3), 4.2, font);
    draw_title(image, {0, 0, 320, 240}, "Sinus rhythm", font);
    return image.rgb;
  };
  EXPECT_EQ(draw(), draw());
}

}  // namespace
}  // namespace systole::overlay
