// End-to-end: the command line from a scene to files, as a user runs it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "encode/png.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kHeart = source("scenes/heart.yaml");
/// Small and short, so end-to-end tests stay quick.
const std::string kSmall = " -D output.width=320 -D output.height=240 -D 'output.duration=1 s' ";

TEST(Cli, ValidatePrintsTheModel) {
  const auto r = run(systole() + " validate " + kHeart);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* fact : {"vertices", "triangles", "region left_ventricle", "region aorta", "pinned", "springs",
                           "volume constraint", "dt 5.55", "300 frames"}) {
    EXPECT_NE(r.output.find(fact), std::string::npos) << "missing '" << fact << "' in:\n" << r.output;
  }
}

TEST(Cli, SceneErrorsNameFileLineAndKey) {
  const auto dir = scratch("scene_error");
  write_file(dir / "typo.yaml",
             "organs:\n  - name: heart\n    mesh: {procedural: heart}\n    body: {stifness: 400 N/m}\n");
  const auto r = run(systole() + " validate " + (dir / "typo.yaml").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("typo.yaml:4:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stifness"), std::string::npos) << r.output;
}

TEST(Cli, ValidateFindsAChamberTheMeshLacks) {
  // Only the built mesh knows its chambers: validate resolves the overlay as render does.
  const auto r = run(systole() + " validate " + source("scenes/heart-labels.yaml") +
                     " -D overlay.traces.1.chamber=left_ventricel");
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("heart-labels.yaml:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no chamber named 'left_ventricel'"), std::string::npos) << r.output;
}

TEST(Cli, MissingSceneIsNoInput) {
  const auto r = run(systole() + " validate /nonexistent/scene.yaml");
  EXPECT_EQ(r.exit_code, 66) << r.output;
}

TEST(Cli, BadUsageIsUsageError) {
  EXPECT_EQ(run(systole() + " render").exit_code, 64);
  EXPECT_EQ(run(systole() + " frobnicate").exit_code, 64);
}

TEST(Cli, InfoNamesTheRendererAndEncoder) {
  const auto r = run(systole() + " info");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("libx264"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("libavcodec"), std::string::npos) << r.output;
}

TEST(Cli, RendersAnMp4ThatPlaysEverywhere) {
  const auto dir = scratch("mp4");
  const auto video = dir / "heart.mp4";
  const auto r = run(systole() + " render " + kHeart + kSmall + "-o " + video.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ms/frame"), std::string::npos) << "per-stage summary:\n" << r.output;
  const auto probe = run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                         "stream=codec_name,profile,pix_fmt,width,height,r_frame_rate,nb_read_frames,color_space,"
                         "color_range:format=duration -of default=noprint_wrappers=1 " + video.string());
  ASSERT_EQ(probe.exit_code, 0) << probe.output;
  for (const char* line : {"codec_name=h264", "profile=High", "pix_fmt=yuv420p", "width=320", "height=240",
                           "r_frame_rate=30/1", "nb_read_frames=30", "color_space=bt709", "color_range=tv",
                           "duration=1.000000"}) {
    EXPECT_NE(probe.output.find(line), std::string::npos) << "missing " << line << " in:\n" << probe.output;
  }
  // +faststart: the index (moov) comes before the media data (mdat).
  const std::string bytes = read_file(video);
  const auto moov = bytes.find("moov"), mdat = bytes.find("mdat");
  ASSERT_NE(moov, std::string::npos);
  ASSERT_NE(mdat, std::string::npos);
  EXPECT_LT(moov, mdat);
}

TEST(Cli, FrameShowsTheOrganInTheMiddleAndBackgroundAtTheEdges) {
  const auto dir = scratch("pixels");
  const auto r = run(systole() + " render " + kHeart + kSmall + "-D 'output.duration=0.1 s' --no-video --png " +
                     (dir / "frames").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image img = encode::read_png(dir / "frames" / encode::frame_file_name(0, 3));
  ASSERT_EQ(img.width, 320);
  ASSERT_EQ(img.height, 240);
  // Background [0.06, 0.07, 0.09] in the scene's default, written as sRGB bytes.
  const int bg[3] = {15, 18, 23};
  for (auto [x, y] : {std::pair{0, 0}, {319, 0}, {0, 239}, {319, 239}, {5, 120}, {314, 120}}) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.pixel(x, y)[c], bg[c], 1) << "background at " << x << "," << y;
  }
  const auto* centre = img.pixel(160, 125);
  EXPECT_GT(centre[0], centre[1] + 30) << "the organ is red in the middle of the frame";
  EXPECT_GT(centre[0], centre[2] + 30);
}


TEST(Cli, FailedRenderLeavesTheEarlierOutputUntouched) {
  const auto dir = scratch("atomic");
  const auto video = dir / "clip.mp4";
  write_file(video, "an earlier clip that must survive");
  // Gravity far beyond what the springs hold tears the free part from the pinned vessels:
  // the health check stops the run part-way, after the video was opened.
  const auto r = run(systole() + " render " + kHeart + kSmall + "-D 'gravity=[0,-100000,0]' -o " + video.string());
  EXPECT_EQ(r.exit_code, 80) << r.output;
  EXPECT_NE(r.output.find("frame"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Remedy"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(video), "an earlier clip that must survive");
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1) << "no temporary file is left behind";
}

TEST(Cli, TheScenesOutputFolderIsCreated) {
  // As scripts/demo runs it: no -o, so the scene's output.file (out/heart.mp4) is used and
  // its folder made in the working directory.
  const auto dir = scratch("default_output");
  const auto r = run("cd " + dir.string() + " && " + systole() + " render " + kHeart + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "heart.mp4")) << r.output;
}

TEST(Cli, OutputIntoAMissingFolderIsCannotCreate) {
  const auto r = run(systole() + " render " + kHeart + kSmall + "-o /nonexistent/folder/clip.mp4");
  EXPECT_EQ(r.exit_code, 73) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/folder"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace systole::test
