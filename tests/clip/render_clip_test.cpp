// Timing for teaching (docs/teaching-visuals.md): slow motion shows organ time k / (fps *
// factor) at frame k; a loop's last frame flows into its first; captions appear only in
// their time range and fade; title cards open the video. Small clips rendered in-process.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "clip/render_clip.h"
#include "clip/video_format.h"
#include "common/error.h"
#include "encode/encode_test_util.h"
#include "encode/png.h"
#include "overlay/cards.h"
#include "scene/load.h"
#include "support/lock_held_elsewhere.h"
#include "support/run.h"
#include "support/small_heart_clip.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// Renders the listed frames (all when empty) as PNGs into `dir` and reads them back.
std::vector<Image> render_frames(const std::string& yaml, const fs::path& dir, std::vector<int> frames = {},
                                 const fs::path& video = {}) {
  const scene::Scene s = scene::load_from_string(yaml, "teaching.yaml", {});
  clip::RenderRequest request;
  request.png_dir = dir;
  request.video = video;
  request.frames = frames;
  clip::render_clip(s, request);
  if (frames.empty()) {
    for (int f = 0; f < s.output.frame_count(); ++f) frames.push_back(f);
  }
  std::vector<Image> images;
  for (int f : frames) images.push_back(encode::read_png(dir / encode::frame_file_name(f, s.output.frame_count())));
  return images;
}

/// Mean absolute difference per channel. unit: levels
double mean_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
  return sum / a.rgb.size();
}

TEST(SlowMotion, FrameKShowsTheOrganAtKOverFpsTimesFactor) {
  const fs::path dir = scratch("slow_motion");
  // 4x: 0.5 s of organ time over 2 s of video, 60 frames; frame 4k is organ time k / 30 s.
  const std::vector<int> real_frames = {1, 3, 5, 6, 9};
  std::vector<int> slow_frames;
  for (int k : real_frames) slow_frames.push_back(4 * k);
  const auto slow = render_frames(small_heart_scene("duration: 0.5 s, slow_motion: 4"), dir / "slow", slow_frames);
  const auto real = render_frames(small_heart_scene("duration: 0.5 s"), dir / "real", real_frames);
  for (std::size_t i = 0; i < slow.size(); ++i) {
    // The same steps lead to both: the same bits.
    EXPECT_EQ(slow[i].rgb, real[i].rgb) << "slow-motion frame " << slow_frames[i] << " vs frame " << real_frames[i];
  }
  // And the frames in between are new moments, not repeats.
  const auto between = render_frames(small_heart_scene("duration: 0.5 s, slow_motion: 4"), dir / "between", {21, 22});
  EXPECT_GT(mean_difference(between[0], slow[2]), 0.0);
  EXPECT_GT(mean_difference(between[1], between[0]), 0.0);
}

TEST(SlowMotion, ActivationColoursFollowOrganTimeNotVideoTime) {
  // color_by activation colours each region by its drive at the organ time the frame shows:
  // slowed 4x, frame 4k is organ time k / 30 s, so it matches the real-time frame k bit for
  // bit (colouring by video time, frame 4k would show the beat four times further on).
  const fs::path dir = scratch("slow_activation");
  std::string slow_yaml = small_heart_scene("duration: 0.5 s, slow_motion: 4");
  std::string real_yaml = small_heart_scene("duration: 0.5 s");
  for (std::string* yaml : {&slow_yaml, &real_yaml}) {
    const std::string organ = "  - name: heart\n";
    yaml->insert(yaml->find(organ) + organ.size(), "    color_by: activation\n");
  }
  const auto slow = render_frames(slow_yaml, dir / "slow", {8, 20});
  const auto real = render_frames(real_yaml, dir / "real", {2, 5});
  EXPECT_EQ(slow[0].rgb, real[0].rgb) << "slow-motion frame 8 vs frame 2";
  EXPECT_EQ(slow[1].rgb, real[1].rgb) << "slow-motion frame 20 vs frame 5";
  EXPECT_GT(mean_difference(real[0], real[1]), 0.0) << "the colours change with the beat";
}

/// How far the last frame is from the first, against the largest step between neighbours.
struct Seam {
  double last_to_first = 0;      ///< unit: levels
  double largest_step = 0;       ///< unit: levels
};

Seam seam_of(const std::vector<Image>& frames) {
  Seam s;
  s.last_to_first = mean_difference(frames.back(), frames.front());
  for (std::size_t i = 1; i < frames.size(); ++i) s.largest_step = std::max(s.largest_step, mean_difference(frames[i], frames[i - 1]));
  return s;
}

TEST(Loop, LastFrameFlowsIntoTheFirst) {
  const fs::path dir = scratch("loop");
  // One beat (0.8333 s = 25 frames) after two beats of settling.
  const auto looped = render_frames(small_heart_scene("duration: 0.8 s, loop: true, settle_cycles: 2"), dir / "loop");
  ASSERT_EQ(looped.size(), 25u);
  const Seam on = seam_of(looped);
  // Without the loop: 1.1 s (1.3 beats) from rest; the last frame is mid-beat, far from the first.
  const auto plain = render_frames(small_heart_scene("duration: 1.1 s"), dir / "plain");
  const Seam off = seam_of(plain);
  std::printf("loop on: last->first %.3f levels, largest step %.3f; loop off: last->first %.3f, largest step %.3f\n",
              on.last_to_first, on.largest_step, off.last_to_first, off.largest_step);
  // Measured: loop on 0.08 levels against steps up to 0.50; loop off 0.64 against 0.51.
  EXPECT_LE(on.last_to_first, on.largest_step) << "the seam is no bigger than a step between neighbouring frames";
  EXPECT_GT(off.last_to_first, off.largest_step) << "without loop the seam is a jump bigger than any step";
  EXPECT_LT(on.last_to_first, 0.25 * off.last_to_first);
  // Frame 25 (one past the end) is frame 0 again, nearly exactly once settled.
  const auto twice = render_frames(small_heart_scene("duration: 1.6 s, loop: true, settle_cycles: 2"), dir / "twice", {0, 25});
  EXPECT_LT(mean_difference(twice[0], twice[1]), 0.25 * on.largest_step);
}

TEST(Captions, ShowOnlyInTheirTimeRangeAndFade) {
  const fs::path dir = scratch("captions");
  // 0.2 s to 0.6 s with 0.1 s fades, at 30 fps: frames 6 (t = 0.2, opacity 0) to 17.
  const std::string caption = "captions:\n  - {text: \"Systole\", from: 0.2 s, to: 0.6 s, fade: 0.1 s, size: 0.12}\n";
  const auto with = render_frames(small_heart_scene("duration: 0.8 s", caption), dir / "with");
  const auto without = render_frames(small_heart_scene("duration: 0.8 s"), dir / "without");
  ASSERT_EQ(with.size(), without.size());
  std::vector<double> strength;
  for (std::size_t f = 0; f < with.size(); ++f) {
    double sum = 0;
    int lowest_changed_row = with[f].height;
    for (int y = 0; y < with[f].height; ++y)
      for (int x = 0; x < with[f].width * 3; ++x) {
        const int d = std::abs(int(with[f].row(y)[x]) - int(without[f].row(y)[x]));
        sum += d;
        if (d > 0) lowest_changed_row = std::min(lowest_changed_row, y);
      }
    strength.push_back(sum);
    const double t = f / 30.0;
    if (t < 0.2 + 1e-9 || t >= 0.6 - 1e-9) {
      EXPECT_EQ(sum, 0) << "frame " << f << " (t = " << t << " s) is outside the caption's range";
    } else {
      EXPECT_GT(sum, 0) << "frame " << f << " should show the caption";
      EXPECT_GE(lowest_changed_row, with[f].height * 3 / 4) << "the caption sits at the bottom (frame " << f << ")";
    }
  }
  // Full strength from t = 0.3 s (frame 9); frames 7 and 8 fade in at 1/3 and 2/3. The
  // difference a caption makes depends a little on the beating heart behind its band.
  const double full = strength[12];
  EXPECT_NEAR(strength[9], full, 0.05 * full);
  EXPECT_GT(strength[7], 0.2 * full);
  EXPECT_LT(strength[7], 0.5 * full);
  EXPECT_GT(strength[8], 0.5 * full);
  EXPECT_LT(strength[8], 0.8 * full);
  // ...and out: frame 16 (t = 0.533 s) at 2/3, frame 17 (0.567 s) at 1/3.
  EXPECT_GT(strength[17], 0.2 * full);
  EXPECT_LT(strength[17], 0.5 * full);
}

TEST(Captions, FadeOpacityRampsAtBothEnds) {
  EXPECT_EQ(overlay::fade_opacity(0.1, 0.2, 0.6, 0.1), 0);
  EXPECT_EQ(overlay::fade_opacity(0.2, 0.2, 0.6, 0.1), 0);
  EXPECT_NEAR(overlay::fade_opacity(0.25, 0.2, 0.6, 0.1), 0.5, 1e-12);
  EXPECT_EQ(overlay::fade_opacity(0.4, 0.2, 0.6, 0.1), 1);
  EXPECT_NEAR(overlay::fade_opacity(0.55, 0.2, 0.6, 0.1), 0.5, 1e-12);
  EXPECT_EQ(overlay::fade_opacity(0.6, 0.2, 0.6, 0.1), 0);
  EXPECT_EQ(overlay::fade_opacity(0.3, 0.2, 0.6, 0), 1);
}

TEST(TitleCard, OpensTheVideoThenTheClipFollowsExactly) {
  const fs::path dir = scratch("title_card");
  const std::string cards = "cards:\n  - {text: \"The heart\\nsinus rhythm\", duration: 1 s, fade: 0.3 s}\n";
  // Lossless FFV1, so the clip's frames in the video are the PNG frames bit for bit.
  const auto clip = render_frames(small_heart_scene("duration: 0.5 s", cards), dir / "png", {}, dir / "clip.mkv");
  const auto video = encode::test::decode_rgb(dir / "clip.mkv");
  ASSERT_EQ(video.size(), 30u + clip.size()) << "30 card frames, then the clip's 15";
  for (std::size_t f = 0; f < clip.size(); ++f) EXPECT_EQ(video[30 + f].rgb, clip[f].rgb) << "clip frame " << f;
  // The card: the background colour alone at its first frame, text in the middle at full
  // opacity, and fading out again.
  const Image& first = video[0];
  EXPECT_TRUE(std::all_of(first.rgb.begin(), first.rgb.end(), [&](std::uint8_t v) { return v == first.rgb[0] || v == first.rgb[1] || v == first.rgb[2]; }));
  auto brightness = [](const Image& im) {
    double sum = 0;
    for (std::uint8_t v : im.rgb) sum += v;
    return sum;
  };
  const double full = brightness(video[15]), in = brightness(video[4]), out = brightness(video[27]);
  EXPECT_GT(full, brightness(first) * 1.05);
  EXPECT_GT(in, brightness(first));
  EXPECT_LT(in, full);
  EXPECT_GT(out, brightness(first));
  EXPECT_LT(out, full);
}

TEST(OutputFormat, TheExtensionOfDashOChoosesTheFormat) {
  const fs::path dir = scratch("format_by_extension");
  const std::string scene = dir / "heart.yaml";
  write_file(scene, small_heart_scene("duration: 0.2 s"));
  for (const char* ext : {"gif", "webm"}) {
    const fs::path video = dir / (std::string("clip.") + ext);
    const auto r = run(systole() + " render " + scene + " -o " + video.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto probe = run("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=codec_name,nb_read_frames,width "
                           "-of default=noprint_wrappers=1 " + video.string());
    EXPECT_NE(probe.output.find(std::string("codec_name=") + (ext == std::string("gif") ? "gif" : "vp9")), std::string::npos) << probe.output;
    EXPECT_NE(probe.output.find("nb_read_frames=6"), std::string::npos) << probe.output;
    EXPECT_NE(probe.output.find("width=160"), std::string::npos) << probe.output;
  }
}

TEST(OutputFormat, AGifFasterThan50FpsIsRefusedBeforeAnyWork) {
  const fs::path dir = scratch("gif_too_fast");
  const std::string scene = dir / "heart.yaml";
  write_file(scene, small_heart_scene("duration: 0.2 s"));
  write_file(dir / "clip.gif", "earlier");
  const auto r = run(systole() + " render " + scene + " -D output.fps=60 -o " + (dir / "clip.gif").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("GIF encoder: fps 60"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(dir / "clip.gif"), "earlier");
  // In the scene, the same mistake names the line.
  std::string yaml = small_heart_scene("duration: 0.2 s, format: gif");
  yaml.replace(yaml.find("fps: 30"), 7, "fps: 60");
  write_file(scene, yaml);
  const auto v = run(systole() + " validate " + scene);
  EXPECT_EQ(v.exit_code, 65) << v.output;
  EXPECT_NE(v.output.find("heart.yaml:11:"), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("output.fps: 60 is outside (0, 50] for a GIF"), std::string::npos) << v.output;
}

TEST(OutputFormat, ASecondRunOfOneOutputIsRefusedBeforeTheWorldIsBuilt) {
  const fs::path dir = scratch("claimed_first");
  LockHeldElsewhere first(dir / "clip.mp4");  // As a first run would while it renders.
  ASSERT_TRUE(first.held());
  const scene::Scene s = scene::load_from_string(small_heart_scene("duration: 0.2 s"), "teaching.yaml", {});
  clip::RenderRequest request;
  request.video = dir / "clip.mp4";
  // A world this run may not build: refused for its size only if the claim came after it.
  request.limits.max_vertices = 1;
  ExitCode code = ExitCode::kOk;
  try {
    clip::render_clip(s, request);
  } catch (const Error& e) {
    code = e.code();
  }
  first.release();
  EXPECT_EQ(code, ExitCode::kBusy);
  // Once the first run is gone, the same request fails on what it asks for.
  try {
    clip::render_clip(s, request);
    ADD_FAILURE() << "a world over the limit was built";
  } catch (const Error& e) {
    EXPECT_NE(e.code(), ExitCode::kBusy) << e.what();
  }
}

TEST(OutputFormat, TheDefaultPathTakesTheFormatsExtension) {
  const auto s = scene::load_from_string(small_heart_scene("duration: 0.2 s, format: webm"), "teaching.yaml", {});
  EXPECT_EQ(clip::default_video_path(s), fs::path("out/teaching.webm"));
  EXPECT_EQ(clip::video_format(s, "elsewhere/clip.gif"), encode::VideoFormat::kGif) << "the extension wins";
  EXPECT_EQ(clip::video_format(s, "elsewhere/clip"), encode::VideoFormat::kWebm) << "no extension: the scene's format";
  // Any other extension is a mistake (-o notes.txt would have written a video called notes.txt).
  try {
    clip::video_format(s, "elsewhere/clip.txt");
    FAIL() << "a .txt output was accepted";
  } catch (const systole::Error& e) {
    EXPECT_EQ(e.code(), systole::ExitCode::kUsage);
    EXPECT_NE(std::string(e.what()).find("elsewhere/clip.txt: '.txt' is not a video's extension"), std::string::npos)
        << e.what();
  }
}

TEST(OutputFormat, EveryFormatIsTheSameBytesOnEveryRun) {
  const fs::path dir = scratch("format_determinism");
  // With sound (AAC, Opus, FLAC: one thread, zeroed padding), a subtitle track and chapters.
  const std::string yaml = small_heart_scene("duration: 0.3 s, loop: false, slow_motion: 2",
                                 "captions:\n  - {text: \"Same bits\", from: 0.1 s, to: 0.5 s, fade: 0.1 s}\n"
                                 "chapters:\n  - {title: \"One\", at: 0.2 s}\n"
                                 "audio: {heart: {s3: {}, murmur: {}}, click: {rate: 90 bpm}}\n");
  for (const char* ext : {"mkv", "webm", "gif", "mp4"}) {
    std::string bytes[2];
    for (int run = 0; run < 2; ++run) {
      const fs::path video = dir / (std::to_string(run) + "." + ext);
      render_frames(yaml, dir / ("png" + std::to_string(run) + ext), {}, video);
      bytes[run] = read_file(video);
    }
    EXPECT_FALSE(bytes[0].empty()) << ext;
    EXPECT_TRUE(bytes[0] == bytes[1]) << ext << " differs between two renders of the same scene";
  }
}

}  // namespace
}  // namespace systole::test
