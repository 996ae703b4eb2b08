// The clip's frames and their organ times (scene/output.h), and the views' layout in the
// frame (scene/teaching.h): what the frame loop and the renderer take from the scene.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scene/output.h"
#include "scene/teaching.h"

namespace systole::scene {
namespace {

TEST(OutputTiming, FramesAreDurationTimesRateTimesSlowMotion) {
  Output o;
  o.duration_s = 10;
  o.fps = 30;
  EXPECT_EQ(o.frame_count(), 300);
  EXPECT_DOUBLE_EQ(o.frame_period_s(), 1.0 / 30);
  o.slow_motion = 4;  // Four times slower: four times the frames of the same organ time.
  EXPECT_EQ(o.frame_count(), 1200);
  EXPECT_DOUBLE_EQ(o.frame_period_s(), 1.0 / 120);
  o.slow_motion = 1;
  o.duration_s = 1.01;
  EXPECT_EQ(o.frame_count(), 30);  // 30.3 rounds to 30.
  o.duration_s = 1.02;
  EXPECT_EQ(o.frame_count(), 31);  // 30.6 rounds to 31.
}

TEST(OutputTiming, ALoopsFramesSplitItsLengthExactly) {
  Output o;
  o.loop = true;
  o.fps = 30;
  o.duration_s = 0.857;  // 25.71 frames: not a whole number.
  ASSERT_EQ(o.frame_count(), 26);
  EXPECT_DOUBLE_EQ(o.frame_period_s(), 0.857 / 26);
  // Frame frame_count() is frame 0 again, one loop later.
  EXPECT_NEAR(o.organ_time_s(o.frame_count()) - o.organ_time_s(0), o.duration_s, 1e-12);
  // Played at the scene's rate, within half a frame a loop.
  EXPECT_NEAR(o.frame_period_s() * o.fps, 1.0, 0.5 / o.frame_count());
}

TEST(OutputTiming, OrganTimeStartsAfterTheSettlingFrames) {
  Output o;
  o.fps = 25;
  o.slow_motion = 2;
  o.start_frame = 40;
  EXPECT_DOUBLE_EQ(o.organ_time_s(0), 40 / 50.0);
  EXPECT_NEAR(o.organ_time_s(10) - o.organ_time_s(9), 1 / 50.0, 1e-15);
  o.start_frame = 0;
  EXPECT_DOUBLE_EQ(o.organ_time_s(0), 0.0);
  EXPECT_DOUBLE_EQ(o.organ_time_s(50), 1.0);  // 50 frames at 50 frames per organ second.
}

TEST(ViewLayout, ViewsTileTheFrameWithoutGapsOrOverlap) {
  for (int n = 1; n <= 10; ++n) {
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1280, 720}, {641, 479}, {100, 37}}) {
      const std::vector<PixelRect> rects = view_rectangles(w, h, n);
      ASSERT_EQ(static_cast<int>(rects.size()), n);
      std::vector<int> cover(static_cast<std::size_t>(w) * h, 0);
      for (const PixelRect& r : rects) {
        EXPECT_GT(r.width, 0);
        EXPECT_GT(r.height, 0);
        for (int y = r.y; y < r.y + r.height; ++y)
          for (int x = r.x; x < r.x + r.width; ++x) ++cover[static_cast<std::size_t>(y) * w + x];
      }
      int twice = 0, none = 0;
      for (int c : cover) twice += c > 1, none += c == 0;
      EXPECT_EQ(twice, 0) << n << " views on " << w << "x" << h;
      // A full grid covers the frame; a partial last row leaves the rest of it empty.
      const int columns = n <= 3 ? n : static_cast<int>(std::ceil(std::sqrt(n)));
      const int rows = (n + columns - 1) / columns;
      if (columns * rows == n) {
        EXPECT_EQ(none, 0) << n << " views on " << w << "x" << h;
      }
    }
  }
}

TEST(ViewLayout, UpToThreeViewsShareOneRow) {
  for (int n = 1; n <= 3; ++n) {
    for (const PixelRect& r : view_rectangles(1280, 720, n)) {
      EXPECT_EQ(r.y, 0);
      EXPECT_EQ(r.height, 720);
    }
  }
  // Four views: a 2 x 2 grid of equal quarters.
  const auto four = view_rectangles(1280, 720, 4);
  ASSERT_EQ(four.size(), 4u);
  for (const PixelRect& r : four) {
    EXPECT_EQ(r.width, 640);
    EXPECT_EQ(r.height, 360);
  }
  EXPECT_TRUE(view_rectangles(1280, 720, 0).empty());
}

}  // namespace
}  // namespace systole::scene
