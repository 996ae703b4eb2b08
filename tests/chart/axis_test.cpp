// Axes: values map where they should, ticks fall on round numbers, tick labels are short.

#include <gtest/gtest.h>

#include "chart/axis.h"

namespace systole::chart {
namespace {

TEST(Axis, LogAxisMapsDecadesEvenly) {
  const Axis axis{"", Scale::kLog, 1, 100};
  EXPECT_DOUBLE_EQ(axis_fraction(axis, 1), 0.0);
  EXPECT_NEAR(axis_fraction(axis, 10), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(axis_fraction(axis, 100), 1.0);
  EXPECT_EQ(ticks(Axis{"", Scale::kLog, 0.5, 2000}), (std::vector<double>{1, 10, 100, 1000}));
  EXPECT_EQ(ticks(Axis{"", Scale::kLog, 0.95, 3.5}), (std::vector<double>{1, 2, 3}));
}

TEST(Axis, LinearTicksAreRound) {
  const auto t = ticks(Axis{"", Scale::kLinear, 0.3, 9.7});
  EXPECT_EQ(t, (std::vector<double>{2, 4, 6, 8}));
}

TEST(Axis, TickTextIsShortAndRoundOffNearZeroIsZero) {
  EXPECT_EQ(tick_text(0.25), "0.25");
  EXPECT_EQ(tick_text(1e-17), "0");
  EXPECT_EQ(tick_text(2000), "2000");
}

}  // namespace
}  // namespace systole::chart
