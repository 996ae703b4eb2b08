// Screen rectangles for the teaching overlays (overlay/layout.h): edges, containment and
// overlap of half-open rectangles, corners with their margins, and sizes scaled to the frame.

#include "overlay/layout.h"

#include <gtest/gtest.h>

namespace systole::overlay {
namespace {

TEST(Layout, ARectangleIsHalfOpen) {
  const Rect r{10, 20, 30, 40};
  EXPECT_EQ(r.right(), 40);
  EXPECT_EQ(r.bottom(), 60);
  EXPECT_TRUE(r.contains(10, 20));
  EXPECT_TRUE(r.contains(39.9, 59.9));
  EXPECT_FALSE(r.contains(40, 30));  // The right and bottom edges are outside.
  EXPECT_FALSE(r.contains(20, 60));
  EXPECT_FALSE(r.contains(9.99, 30));
}

TEST(Layout, RectanglesOverlapOnlyWhenTheyShareAPixel) {
  const Rect a{0, 0, 10, 10};
  EXPECT_TRUE(a.overlaps({9, 9, 5, 5}));
  EXPECT_FALSE(a.overlaps({10, 0, 5, 5}));  // Touching edges share no pixel.
  EXPECT_FALSE(a.overlaps({0, 10, 5, 5}));
  EXPECT_TRUE(a.overlaps({2, 2, 1, 1}));  // Inside.
  EXPECT_TRUE(Rect({2, 2, 1, 1}).overlaps(a));
  EXPECT_TRUE(a.overlaps({-5, -5, 30, 30}));  // Around.
}

TEST(Layout, GrowingMovesEveryEdgeOut) {
  const Rect g = Rect{10, 10, 20, 5}.grown(3);
  EXPECT_EQ(g.x, 7);
  EXPECT_EQ(g.y, 7);
  EXPECT_EQ(g.right(), 33);
  EXPECT_EQ(g.bottom(), 18);
  const Rect s = g.grown(-3);
  EXPECT_EQ(s.x, 10);
  EXPECT_EQ(s.width, 20);
}

TEST(Layout, CornersKeepTheirMarginInsideTheFrame) {
  const Rect frame{100, 50, 640, 360};
  const int w = 80, h = 30, m = 12;
  for (Corner c : {Corner::kTopLeft, Corner::kTopRight, Corner::kBottomLeft, Corner::kBottomRight}) {
    const Rect r = corner_rect(frame, c, w, h, m);
    EXPECT_EQ(r.width, w);
    EXPECT_EQ(r.height, h);
    const bool right = c == Corner::kTopRight || c == Corner::kBottomRight;
    const bool bottom = c == Corner::kBottomLeft || c == Corner::kBottomRight;
    EXPECT_EQ(right ? frame.right() - r.right() : r.x - frame.x, m);
    EXPECT_EQ(bottom ? frame.bottom() - r.bottom() : r.y - frame.y, m);
    EXPECT_TRUE(frame.contains(r.x, r.y));
    EXPECT_TRUE(frame.contains(r.right() - 1, r.bottom() - 1));
  }
  // Opposite corners of a big enough frame never overlap.
  EXPECT_FALSE(corner_rect(frame, Corner::kTopLeft, w, h, m).overlaps(corner_rect(frame, Corner::kBottomRight, w, h, m)));
}

TEST(Layout, SizesScaleWithTheFrameHeightFrom720Lines) {
  EXPECT_EQ(scaled_px(20, 720), 20);
  EXPECT_EQ(scaled_px(20, 1440), 40);
  EXPECT_EQ(scaled_px(20, 240), 7);  // 6.67 rounds to 7.
  EXPECT_EQ(scaled_px(1, 100), 1);   // Never below one pixel.
  EXPECT_EQ(scaled_px(0, 720), 1);
}

}  // namespace
}  // namespace systole::overlay
