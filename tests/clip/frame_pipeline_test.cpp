// ctest-labels: slow-under-sanitizers
// The overlapped frame loop: the stages hand frames on in order, a failure anywhere stops
// the run with that error, and a clip comes out bit for bit the same with and without the
// overlap.

#include "clip/frame_pipeline.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "clip/render_clip.h"
#include "scene/load.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

TEST(FramePipeline, EveryStageSeesEveryFrameInOrderThroughItsSlot) {
  constexpr int kCount = 50, kDepth = 3;
  for (const bool overlap : {false, true}) {
    std::vector<int> slot_value(kDepth, -1), image_value(kDepth, -1), consumed;
    clip::PipelineStages stages;
    stages.produce = [&](int i, int slot) { slot_value[slot] = 10 * i; };
    stages.render = [&](int i, int slot) {
      ASSERT_EQ(slot_value[slot], 10 * i);  // Not yet overwritten by frame i + depth.
      image_value[slot] = slot_value[slot] + 1;
    };
    stages.consume = [&](int i, int slot) {
      ASSERT_EQ(image_value[slot], 10 * i + 1);
      consumed.push_back(i);
    };
    clip::run_frame_pipeline(kCount, kDepth, overlap, stages);
    ASSERT_EQ(consumed.size(), static_cast<std::size_t>(kCount)) << "overlap " << overlap;
    for (int i = 0; i < kCount; ++i) EXPECT_EQ(consumed[i], i);
  }
}

TEST(FramePipeline, TheFirstFailureStopsEveryStageAndIsRethrown) {
  for (const int failing_stage : {0, 1, 2}) {
    std::atomic<int> consumed = 0;
    clip::PipelineStages stages;
    const auto maybe_fail = [&](int stage, int i) {
      if (stage == failing_stage && i == 7) throw std::runtime_error("stage " + std::to_string(stage));
    };
    stages.produce = [&](int i, int) { maybe_fail(0, i); };
    stages.render = [&](int i, int) { maybe_fail(1, i); };
    stages.consume = [&](int i, int) {
      maybe_fail(2, i);
      ++consumed;
    };
    try {
      clip::run_frame_pipeline(1000, 3, true, stages);
      ADD_FAILURE() << "no exception from stage " << failing_stage;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "stage " + std::to_string(failing_stage));
    }
    EXPECT_LE(consumed.load(), 7) << "frames after the failure were not encoded";
  }
}

TEST(FramePipeline, TheClipIsTheSameBitsWithAndWithoutOverlap) {
  const auto dir = scratch("overlap");
  auto scene = scene::load(source("scenes/heart.yaml"),
                           {"output.width=320", "output.height=240", "output.duration=1 s"});
  for (const bool overlap : {true, false}) {
    const std::string name = overlap ? "overlap" : "serial";
    clip::RenderRequest request;
    request.video = dir / (name + ".mp4");
    request.png_dir = dir / name;
    request.overlap = overlap;
    const auto times = clip::render_clip(scene, request);
    EXPECT_EQ(times.frames, 30);
  }
  EXPECT_EQ(read_file(dir / "overlap.mp4"), read_file(dir / "serial.mp4")) << "the videos differ";
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir / "serial")) {
    const auto name = entry.path().filename();
    EXPECT_EQ(read_file(dir / "overlap" / name), read_file(entry.path())) << name << " differs";
    ++compared;
  }
  EXPECT_EQ(compared, 30);
}

}  // namespace
}  // namespace systole::test
