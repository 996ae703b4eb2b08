// ctest-labels: no-sanitizers
// Frames that can be trusted: a selected frame is the same file as in a full render, and the
// same frames come out bit for bit at 1 and 2 rasterizer threads and across runs.

#include <gtest/gtest.h>

#include <set>

#include "encode/png.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kHeart = source("scenes/heart.yaml");
/// 320x240, 1 s = 30 frames.
const std::string kSmall = " -D output.width=320 -D output.height=240 -D 'output.duration=1 s' ";

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

TEST(RenderFrames, SelectedFramesEqualTheFullRenderBitForBit) {
  const auto dir = scratch("frames_vs_full");
  const auto full = run(systole() + " render " + kHeart + kSmall + "--no-video --png " + (dir / "full").string());
  ASSERT_EQ(full.exit_code, 0) << full.output;
  const auto some = run(systole() + " render " + kHeart + kSmall + "--frames 29,0,7..9,8 --png " + (dir / "some").string());
  ASSERT_EQ(some.exit_code, 0) << some.output;
  EXPECT_NE(some.output.find("wrote 5 PNG frames"), std::string::npos) << some.output;
  const std::set<std::string> expected = {"frame_00000.png", "frame_00007.png", "frame_00008.png", "frame_00009.png",
                                          "frame_00029.png"};
  EXPECT_EQ(files_in(dir / "some"), expected) << "only the listed frames, named as in the full render";
  EXPECT_EQ(files_in(dir / "full").size(), 30u);
  for (const auto& name : expected) {
    EXPECT_EQ(read_file(dir / "some" / name), read_file(dir / "full" / name)) << name << " differs from the full render";
  }
  EXPECT_EQ(some.output.find(".mp4"), std::string::npos) << "a selection writes no video unless -o asks:\n"
                                                          << some.output;
}

TEST(RenderFrames, AConsecutiveRangeCanBeAVideoOfJustThoseFrames) {
  const auto dir = scratch("frames_video");
  const auto video = dir / "range.mp4";
  const auto r = run(systole() + " render " + kHeart + kSmall + "--frames 10..14 -o " + video.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto probe = run("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                         "-of default=noprint_wrappers=1 " + video.string());
  EXPECT_NE(probe.output.find("nb_read_frames=5"), std::string::npos) << probe.output;
}

TEST(RenderFrames, BadSelectionsAreUsageErrorsThatExplain) {
  const auto dir = scratch("frames_usage");
  const std::string png = " --png " + (dir / "png").string();
  auto r = run(systole() + " render " + kHeart + kSmall + "--frames 0..30" + png);
  EXPECT_EQ(r.exit_code, 64) << r.output;
  EXPECT_NE(r.output.find("frame 30 is past the clip's end: it has 30 frames (0..29)"), std::string::npos) << r.output;
  r = run(systole() + " render " + kHeart + kSmall + "--frames 3..x" + png);
  EXPECT_EQ(r.exit_code, 64) << r.output;
  EXPECT_NE(r.output.find("Accepted forms"), std::string::npos) << r.output;
  r = run(systole() + " render " + kHeart + kSmall + "--frames 0,9");
  EXPECT_EQ(r.exit_code, 64) << r.output;
  EXPECT_NE(r.output.find("add --png DIR"), std::string::npos) << r.output;
  r = run(systole() + " render " + kHeart + kSmall + "--frames 0,9 -o " + (dir / "x.mp4").string() + png);
  EXPECT_EQ(r.exit_code, 64) << r.output;
  EXPECT_NE(r.output.find("a video needs consecutive frames"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "png")) << "nothing is written for a refused selection";
}

TEST(Determinism, SameFramesAtOneAndTwoRasterizerThreadsAndAcrossRuns) {
  // LP_NUM_THREADS is read when the process creates its first GL context, so each run is a
  // child process with its own setting.
  const auto dir = scratch("determinism");
  const std::string frames = " --frames 0..24:6 --no-video --png ";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"LP_NUM_THREADS=1", "threads1"}, {"LP_NUM_THREADS=2", "threads2"}, {"LP_NUM_THREADS=2", "threads2_again"}};
  for (const auto& [env, name] : runs) {
    const auto r = run(env + " " + systole() + " render " + kHeart + kSmall + frames + (dir / name).string());
    ASSERT_EQ(r.exit_code, 0) << env << ": " << r.output;
  }
  const auto names = files_in(dir / "threads1");
  ASSERT_EQ(names.size(), 5u);
  for (const auto& name : names) {
    const std::string reference = read_file(dir / "threads1" / name);
    const Image image = encode::read_png(dir / "threads1" / name);
    for (const char* other : {"threads2", "threads2_again"}) {
      EXPECT_EQ(read_file(dir / other / name), reference) << name << ": " << other << " differs from 1 thread";
      EXPECT_EQ(encode::read_png(dir / other / name).rgb, image.rgb) << name << ": " << other;
    }
  }
}

TEST(Determinism, TeachingVisualsAreTheSameBitsAtOneAndTwoRasterizerThreads) {
  const auto dir = scratch("teaching_visuals_determinism");
  for (const char* scene : {"chest-transparent", "heart-cutaway", "heart-strain"}) {
    for (const char* threads : {"1", "2"}) {
      const auto out = dir / (std::string(scene) + "_" + threads);
      const auto r = run(std::string("LP_NUM_THREADS=") + threads + " " + systole() + " render " +
                         source(std::string("scenes/") + scene + ".yaml") +
                         " -D output.width=240 -D output.height=136 --frames 9 --no-video --png " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    const std::string one = read_file(dir / (std::string(scene) + "_1") / "frame_00009.png");
    EXPECT_FALSE(one.empty()) << scene;
    EXPECT_EQ(read_file(dir / (std::string(scene) + "_2") / "frame_00009.png"), one) << scene;
  }
}

}  // namespace
}  // namespace systole::test
