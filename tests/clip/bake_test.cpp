// ctest-labels: slow-under-sanitizers
// Bakes: a clip simulated once, rendered by frame ranges, joined without re-encoding.

#include <gtest/gtest.h>

#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kHeart = source("scenes/heart.yaml");
constexpr int kW = 96, kH = 64, kFrames = 30;
/// Lossless (crf 0): each segment is encoded on its own, from a key frame, so its bits
/// differ from a single run's; what must match is every decoded frame, exactly.
const std::string kSmall =
    " -D output.width=96 -D output.height=64 -D 'output.duration=1 s' -D output.antialias=0 -D output.crf=0 ";

/// Every decoded frame, as packed RGB.
std::string decoded(const fs::path& video) {
  const auto raw = video.string() + ".rgb";
  const auto r = run("ffmpeg -v error -y -i " + video.string() + " -f rawvideo -pix_fmt rgb24 " + raw);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return read_file(raw);
}

TEST(Bake, SegmentsFromABakeJoinIntoTheSingleRunVideoFrameForFrame) {
  const auto dir = scratch("bake_segments");
  const auto bake = dir / "heart.bake";
  auto r = run(systole() + " bake " + kHeart + kSmall + "-o " + bake.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run(systole() + " render " + kHeart + kSmall + "-o " + (dir / "single.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const auto& [range, part] : {std::pair{"0..11", "a.mp4"}, {"12..20", "b.mp4"}, {"21..29", "c.mp4"}}) {
    r = run(systole() + " render " + kHeart + kSmall + "--from-bake " + bake.string() + " --frames " + range + " -o " +
            (dir / part).string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  r = run(source("scripts/join-segments") + " " + (dir / "joined.mp4").string() + " " + (dir / "a.mp4").string() +
          " " + (dir / "b.mp4").string() + " " + (dir / "c.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string single = decoded(dir / "single.mp4"), joined = decoded(dir / "joined.mp4");
  ASSERT_EQ(single.size(), std::size_t{kFrames} * kW * kH * 3);
  ASSERT_EQ(joined.size(), single.size()) << "as many frames as the single run";
  const std::size_t n = std::size_t{kW} * kH * 3;
  for (int f = 0; f < kFrames; ++f) {
    EXPECT_TRUE(joined.compare(f * n, n, single, f * n, n) == 0) << "frame " << f << " differs from the single run's";
  }
  // The comparison can fail: the heart moves, so neighbouring frames differ.
  EXPECT_NE(single.compare(0, n, single, 10 * n, n), 0);
  const auto probe = run("ffprobe -v error -show_entries format=duration -of default=noprint_wrappers=1 " +
                         (dir / "joined.mp4").string());
  EXPECT_NE(probe.output.find("duration=1.000000"), std::string::npos) << probe.output;
}

TEST(Bake, FramesFromABakeAreTheSimulatedFramesBitForBit) {
  const auto dir = scratch("bake_pngs");
  const std::string scene = kHeart + " -D output.width=96 -D output.height=64 -D 'output.duration=0.5 s' ";
  ASSERT_EQ(run(systole() + " bake " + scene + "-o " + (dir / "h.bake").string()).exit_code, 0);
  auto r = run(systole() + " render " + scene + "--frames 3,14 --png " + (dir / "sim").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run(systole() + " render " + scene + "--frames 3,14 --from-bake " + (dir / "h.bake").string() + " --png " +
          (dir / "baked").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"frame_00003.png", "frame_00014.png"}) {
    EXPECT_EQ(read_file(dir / "baked" / f), read_file(dir / "sim" / f)) << f;
  }
}

TEST(Bake, ADamagedOrMismatchedBakeIsRefusedWithItsReason) {
  const auto dir = scratch("bake_bad");
  const std::string scene = kHeart + " -D output.width=96 -D output.height=64 -D 'output.duration=0.2 s' ";
  const auto bake = dir / "h.bake";
  ASSERT_EQ(run(systole() + " bake " + scene + "-o " + bake.string()).exit_code, 0);
  const std::string render = systole() + " render " + scene + "--png " + (dir / "f").string() + " --no-video --from-bake ";

  auto r = run(render.substr(0, render.find("--png")) + " -D 'output.duration=0.3 s' --no-video --png " +
               (dir / "f").string() + " --from-bake " + bake.string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("frames"), std::string::npos) << r.output;

  std::string bytes = read_file(bake);
  bytes[bytes.size() / 2] ^= 1;
  write_file(dir / "damaged.bake", bytes);
  r = run(render + (dir / "damaged.bake").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("checksum"), std::string::npos) << r.output;

  write_file(dir / "short.bake", bytes.substr(0, 100));
  EXPECT_EQ(run(render + (dir / "short.bake").string()).exit_code, 65);
  EXPECT_EQ(run(render + (dir / "missing.bake").string()).exit_code, 66);
}

}  // namespace
}  // namespace systole::test
