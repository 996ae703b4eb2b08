// Charts: axes map values where they should, ticks fall on round numbers, points land at
// their coordinates in their colour, text is drawn, bad data is refused.

#include <gtest/gtest.h>

#include "common/error.h"
#include "plot/plot.h"

namespace systole::plot {
namespace {

TEST(Plot, PointsLandWhereTheyBelongInTheirColour) {
  Figure f;
  f.width = 400;
  f.height = 300;
  f.x = {"x", Scale::kLinear, 0, 10};
  f.y = {"y", Scale::kLog, 1, 1000};
  Series s;
  s.color = {200, 0, 0};
  s.marker = Marker::kSquare;
  s.marker_px = 12;
  s.points = {{5, 10, "mid"}};
  f.series = {s};
  const Image image = render(f);
  ASSERT_EQ(image.width, 400);
  ASSERT_EQ(image.height, 300);
  // Same layout as render(): plot area [95, 370] x [30, 225].
  const int px = 95 + (370 - 95) / 2, py = 225 - (225 - 30) / 3;
  const std::uint8_t* p = image.pixel(px, py);
  EXPECT_EQ(p[0], 200);
  EXPECT_EQ(p[1], 0);
  // Some text was set: dark pixels below the axis (tick labels, the axis name).
  int dark = 0;
  for (int y = 230; y < 300; ++y) {
    for (int x = 0; x < 400; ++x) dark += image.pixel(x, y)[0] < 100;
  }
  EXPECT_GT(dark, 50);
}

TEST(Plot, RefusesValuesALogAxisCannotShow) {
  Figure f;
  f.x.scale = Scale::kLog;
  Series s;
  s.points = {{0.0, 1.0, ""}};
  f.series = {s};
  EXPECT_THROW(render(f), Error);
}

}  // namespace
}  // namespace systole::plot
