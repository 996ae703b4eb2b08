// Every output format round-trips: the written file, decoded with libavformat/libavcodec
// and converted back to RGB, has the frames written, at their size, matching the rendered
// RGB within each format's stated tolerance (FFV1 exactly). And the same frames give the
// same bytes (docs/teaching-visuals.md, "Timing and formats").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "encode/gif_writer.h"
#include "encode/palette.h"
#include "encode/video_writer.h"
#include "encode_test_util.h"

namespace systole::encode {
namespace {

using test::scratch_dir;
namespace fs = std::filesystem;

struct Difference {
  double mean_abs = 0;  ///< Mean absolute difference per channel. unit: levels
  int max_abs = 0;      ///< unit: levels
  double psnr_db = 0;   ///< unit: dB (infinite when equal)
};

Difference difference(const Image& a, const Image& b) {
  Difference d;
  double sum = 0, sq = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const int e = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    sum += e, sq += double(e) * e;
    d.max_abs = std::max(d.max_abs, e);
  }
  d.mean_abs = sum / a.rgb.size();
  d.psnr_db = sq == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / (sq / a.rgb.size()));
  return d;
}

constexpr int kWidth = 320, kHeight = 240, kFrames = 12;

VideoSettings settings_for(VideoFormat format) {
  VideoSettings s;
  s.format = format;
  s.width = kWidth;
  s.height = kHeight;
  s.fps = 25;
  s.threads = 1;
  return s;
}

std::vector<Image> clip() {
  std::vector<Image> frames;
  for (int i = 0; i < kFrames; ++i) frames.push_back(test::organ_frame(kWidth, kHeight, i));
  return frames;
}

fs::path write(const fs::path& file, const std::vector<Image>& frames) {
  const auto format = video_format_of(file);
  EXPECT_TRUE(format.has_value()) << file;
  auto sink = open_video(file, settings_for(*format));
  for (std::size_t i = 0; i < frames.size(); ++i) sink->write(frames[i], static_cast<int>(i));
  sink->finish();
  return file;
}

/// Decodes `file` and checks every frame against `frames` within the tolerance.
void expect_round_trip(const fs::path& file, const std::vector<Image>& frames, double min_psnr_db, double max_mean_abs) {
  const auto decoded = test::decode_rgb(file);
  ASSERT_EQ(decoded.size(), frames.size()) << file;
  double worst_psnr = INFINITY, worst_mean = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ASSERT_EQ(decoded[i].width, kWidth);
    ASSERT_EQ(decoded[i].height, kHeight);
    const Difference d = difference(decoded[i], frames[i]);
    EXPECT_GE(d.psnr_db, min_psnr_db) << file.filename() << " frame " << i;
    EXPECT_LE(d.mean_abs, max_mean_abs) << file.filename() << " frame " << i;
    worst_psnr = std::min(worst_psnr, d.psnr_db);
    worst_mean = std::max(worst_mean, d.mean_abs);
  }
  std::printf("%s: worst frame %.1f dB PSNR, mean |error| %.2f levels\n", file.filename().c_str(), worst_psnr, worst_mean);
}

TEST(Formats, ExtensionsNameTheFormat) {
  EXPECT_EQ(video_format_of("a/clip.mp4"), VideoFormat::kMp4);
  EXPECT_EQ(video_format_of("clip.MKV"), VideoFormat::kMkv);
  EXPECT_EQ(video_format_of("clip.webm"), VideoFormat::kWebm);
  EXPECT_EQ(video_format_of("slides/clip.gif"), VideoFormat::kGif);
  EXPECT_FALSE(video_format_of("clip.avi").has_value());
  EXPECT_FALSE(video_format_of("clip").has_value());
  for (auto f : {VideoFormat::kMp4, VideoFormat::kMkv, VideoFormat::kWebm, VideoFormat::kGif})
    EXPECT_EQ(video_format_of(std::string("x.") + extension_of(f)), f);
}

TEST(Formats, Ffv1InMkvIsLosslessRgb) {
  const auto frames = clip();
  const fs::path file = write(scratch_dir() / "clip.mkv", frames);
  const auto decoded = test::decode_rgb(file);
  ASSERT_EQ(decoded.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) EXPECT_EQ(decoded[i].rgb, frames[i].rgb) << "frame " << i;
  const std::string probe = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(probe, "codec_name"), "ffv1");
  EXPECT_EQ(test::json_value(probe, "pix_fmt"), "bgr0");
}

TEST(Formats, Vp9InWebmRoundTrips) {
  const auto frames = clip();
  const fs::path file = write(scratch_dir() / "clip.webm", frames);
  // CRF 32 on smooth shading: measured 40.8 dB, 1.2 levels; the bounds leave room for other libvpx versions.
  expect_round_trip(file, frames, 34, 3.0);
  const std::string probe = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(probe, "codec_name"), "vp9");
  EXPECT_EQ(test::json_value(probe, "color_space"), "bt709");
}

TEST(Formats, H264InMp4RoundTrips) {
  const auto frames = clip();
  // CRF 20, veryfast: measured 41.0 dB, 1.0 levels.
  expect_round_trip(write(scratch_dir() / "clip.mp4", frames), frames, 36, 2.5);
}

TEST(Formats, GifRoundTripsThroughOnePaletteWithExactTiming) {
  const auto frames = clip();
  const fs::path file = write(scratch_dir() / "clip.gif", frames);
  // 256 colours with an ordered dither of +-6 levels: measured 38.6 dB, 2.3 levels.
  expect_round_trip(file, frames, 34, 4.0);
  const std::string probe = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(probe, "codec_name"), "gif");
  // 12 frames at 25 fps: 4 cs each, 0.48 s.
  EXPECT_NEAR(std::stod(test::json_value(probe, "duration", "format")), 0.48, 0.011);
}

TEST(Formats, GifDelaysAddUpAtRatesThatAreNotWholeCentiseconds) {
  const fs::path file = scratch_dir() / "thirty.gif";
  auto sink = open_video(file, [] {
    VideoSettings s = settings_for(VideoFormat::kGif);
    s.fps = 30;  // Delays of 3, 3, 4 cs: 30 frames last exactly 1 s.
    return s;
  }());
  for (int i = 0; i < 30; ++i) sink->write(test::organ_frame(kWidth, kHeight, i), i);
  sink->finish();
  const std::string probe = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(probe, "nb_read_frames"), "30");
  EXPECT_NEAR(std::stod(test::json_value(probe, "duration", "format")), 1.0, 0.011);
}

TEST(Formats, SameFramesGiveTheSameBytes) {
  const auto frames = clip();
  const fs::path dir = scratch_dir();
  for (const char* ext : {"mkv", "webm", "gif", "mp4"}) {
    const std::string a = test::read_bytes(write(dir / (std::string("a.") + ext), frames));
    const std::string b = test::read_bytes(write(dir / (std::string("b.") + ext), frames));
    EXPECT_FALSE(a.empty()) << ext;
    EXPECT_TRUE(a == b) << ext << " differs between two runs";
  }
}

TEST(Formats, GifRefusesFastRatesAndKeepsEarlierOutput) {
  const fs::path dir = scratch_dir();
  EXPECT_THROW(GifWriter(dir / "fast.gif", GifSettings{64, 64, 60}), Error);
  test::write_bytes(dir / "old.gif", "old");
  {
    GifWriter writer(dir / "old.gif", GifSettings{kWidth, kHeight, 25});
    writer.write(test::organ_frame(kWidth, kHeight, 0), 0);
  }  // No finish(): the earlier file stays.
  EXPECT_EQ(test::read_bytes(dir / "old.gif"), "old");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
}

TEST(Palette, FewColoursComeBackExactly) {
  Image image(16, 16);
  const PaletteColor colors[3] = {{10, 20, 30}, {200, 40, 40}, {255, 255, 255}};
  for (int i = 0; i < 256; ++i) {
    const auto& c = colors[i % 3];
    std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
  }
  PaletteBuilder builder;
  builder.add(image);
  const auto palette = builder.build();
  ASSERT_EQ(palette.size(), 3u);
  PaletteMapper mapper(palette, /*dither=*/0);
  std::vector<std::uint8_t> indices;
  mapper.map(image, indices);
  for (int i = 0; i < 256; ++i) EXPECT_EQ(palette[indices[static_cast<std::size_t>(i)]], colors[i % 3]);
}

}  // namespace
}  // namespace systole::encode
