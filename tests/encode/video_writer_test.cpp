#include "encode/video_writer.h"

#include <gtest/gtest.h>

#include "support/error_code.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <algorithm>
#include <array>

#include "common/error.h"
#include "encode_test_util.h"

namespace systole::encode {
namespace {

using test::scratch_dir;
namespace fs = std::filesystem;

// A diagonal gradient that scrolls and a white square that moves one step per frame.
Image moving_frame(int width, int height, int index) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = image.row(y);
    for (int x = 0; x < width; ++x) {
      row[3 * x + 0] = static_cast<std::uint8_t>((x + 4 * index) & 255);
      row[3 * x + 1] = static_cast<std::uint8_t>((y + 2 * index) & 255);
      row[3 * x + 2] = static_cast<std::uint8_t>((x + y) / 4 & 255);
    }
  }
  const int x0 = (index * 5) % (width - 40), y0 = height / 3;
  for (int y = y0; y < y0 + 40; ++y) {
    for (int x = x0; x < x0 + 40; ++x) std::fill_n(image.row(y) + 3 * x, 3, 255);
  }
  return image;
}

Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = r;
    image.rgb[i + 1] = g;
    image.rgb[i + 2] = b;
  }
  return image;
}

VideoSettings small_settings() {
  VideoSettings s;
  s.width = 320;
  s.height = 240;
  s.fps = 30;
  s.threads = 2;
  return s;
}

fs::path write_clip(const fs::path& file, const VideoSettings& s, int frames, int first_index = 0) {
  VideoWriter writer(file, s);
  for (int i = 0; i < frames; ++i) writer.write(moving_frame(s.width, s.height, i), first_index + i);
  EXPECT_EQ(writer.frame_count(), frames);
  writer.finish();
  return file;
}

using systole::test::code_of;

// Only `expected` is left in `dir`: no temporary survives.
void expect_only(const fs::path& dir, const std::vector<std::string>& expected) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, expected);
}

TEST(VideoWriter, ProbesAsHighProfileBt709LimitedRangeWithExactTiming) {
  const fs::path file = write_clip(scratch_dir() / "clip.mp4", small_settings(), 30);
  const std::string json = test::ffprobe_json(file);
  ASSERT_NE(json.find("\"streams\""), std::string::npos) << json;
  EXPECT_EQ(test::json_value(json, "codec_name"), "h264");
  EXPECT_EQ(test::json_value(json, "profile"), "High");
  EXPECT_EQ(test::json_value(json, "pix_fmt"), "yuv420p");
  EXPECT_EQ(test::json_value(json, "width"), "320");
  EXPECT_EQ(test::json_value(json, "height"), "240");
  EXPECT_EQ(test::json_value(json, "color_range"), "tv");
  EXPECT_EQ(test::json_value(json, "color_space"), "bt709");
  EXPECT_EQ(test::json_value(json, "color_primaries"), "bt709");
  EXPECT_EQ(test::json_value(json, "color_transfer"), "bt709");
  EXPECT_EQ(test::json_value(json, "r_frame_rate"), "30/1");
  EXPECT_EQ(test::json_value(json, "avg_frame_rate"), "30/1");
  EXPECT_EQ(test::json_value(json, "nb_frames"), "30");
  EXPECT_EQ(test::json_value(json, "nb_read_frames"), "30");
  EXPECT_EQ(test::json_value(json, "duration", "streams"), "1.000000");  // Not 0.966667.
  EXPECT_EQ(test::json_value(json, "duration", "format"), "1.000000");
  EXPECT_EQ(test::json_value(json, "start_time", "format"), "0.000000");
  EXPECT_EQ(test::json_value(json, "format_name", "format"), "mov,mp4,m4a,3gp,3g2,mj2");
}

TEST(VideoWriter, FaststartPutsMoovBeforeMdat) {
  const fs::path file = write_clip(scratch_dir() / "clip.mp4", small_settings(), 30);
  const std::vector<std::string> boxes = test::top_level_boxes(file);
  ASSERT_FALSE(boxes.empty());
  EXPECT_EQ(boxes.front(), "ftyp");
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin());
  EXPECT_EQ(std::find(boxes.begin(), boxes.end(), std::string("<bad size>")), boxes.end());
}

// Expected BT.709 limited-range Y'CbCr of a full-range RGB colour.
struct Yuv {
  double y, u, v;
};
Yuv bt709_limited(double r, double g, double b) {
  r /= 255, g /= 255, b /= 255;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return {16 + 219 * y, 128 + 224 * (b - y) / 1.8556, 128 + 224 * (r - y) / 1.5748};
}
// And back, as a BT.709 player does.
std::array<double, 3> bt709_to_rgb(double Y, double U, double V) {
  const double y = (Y - 16) / 219, pb = (U - 128) / 224, pr = (V - 128) / 224;
  const double r = y + 1.5748 * pr, b = y + 1.8556 * pb;
  const double g = (y - 0.2126 * r - 0.0722 * b) / 0.7152;
  return {255 * r, 255 * g, 255 * b};
}

TEST(VideoWriter, PrimaryColoursComeBackThroughBt709LimitedRange) {
  const fs::path file = scratch_dir() / "colours.mp4";
  VideoSettings s = small_settings();
  s.crf = 12;
  struct Rgb {
    std::uint8_t r, g, b;
  };
  const std::vector<Rgb> colours = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}, {128, 128, 128}};
  {
    VideoWriter writer(file, s);
    int i = 0;
    for (const Rgb& c : colours) writer.write(solid(s.width, s.height, c.r, c.g, c.b), i++);
    // Orientation: red on the top half, blue on the bottom half.
    Image split = solid(s.width, s.height, 0, 0, 255);
    for (int y = 0; y < s.height / 2; ++y) {
      for (int x = 0; x < s.width; ++x) {
        std::uint8_t* p = split.row(y) + 3 * x;
        p[0] = 255, p[1] = 0, p[2] = 0;
      }
    }
    writer.write(split, i++);
    writer.finish();
  }
  const std::vector<test::YuvFrame> frames = test::decode_all(file);
  ASSERT_EQ(frames.size(), colours.size() + 1);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const Rgb c = colours[i];
    const Yuv want = bt709_limited(c.r, c.g, c.b);
    const test::YuvFrame& f = frames[i];
    const int x = f.width / 2, y = f.height / 2;
    SCOPED_TRACE("colour " + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b));
    // BT.601 would give Y 81 for red, 145 for green: a 3-level tolerance tells them apart.
    EXPECT_NEAR(f.Y(x, y), want.y, 3);
    EXPECT_NEAR(f.U(x, y), want.u, 3);
    EXPECT_NEAR(f.V(x, y), want.v, 3);
    const auto rgb = bt709_to_rgb(f.Y(x, y), f.U(x, y), f.V(x, y));
    EXPECT_NEAR(rgb[0], c.r, 6);
    EXPECT_NEAR(rgb[1], c.g, 6);
    EXPECT_NEAR(rgb[2], c.b, 6);
  }
  const test::YuvFrame& split = frames.back();
  const auto top = bt709_to_rgb(split.Y(10, 10), split.U(10, 10), split.V(10, 10));
  const auto bottom = bt709_to_rgb(split.Y(10, s.height - 10), split.U(10, s.height - 10), split.V(10, s.height - 10));
  EXPECT_GT(top[0], 240);  // Top row first: red stays on top.
  EXPECT_LT(top[2], 15);
  EXPECT_GT(bottom[2], 240);
  EXPECT_LT(bottom[0], 15);
}

TEST(VideoWriter, FractionalFrameRates) {
  EXPECT_EQ(frame_rate_of(29.97).num, 30000);
  EXPECT_EQ(frame_rate_of(29.97).den, 1001);
  EXPECT_EQ(frame_rate_of(30000.0 / 1001).num, 30000);
  EXPECT_EQ(frame_rate_of(23.976).num, 24000);
  EXPECT_EQ(frame_rate_of(59.94).num, 60000);
  EXPECT_EQ(frame_rate_of(30).num, 30);
  EXPECT_EQ(frame_rate_of(30).den, 1);
  EXPECT_EQ(frame_rate_of(12.5).num, 25);
  EXPECT_EQ(frame_rate_of(12.5).den, 2);
  EXPECT_EQ(frame_rate_of(29.5).num, 59);

  VideoSettings s = small_settings();
  s.fps = 29.97;
  const fs::path file = write_clip(scratch_dir() / "ntsc.mp4", s, 30);
  const std::string json = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(json, "r_frame_rate"), "30000/1001");
  EXPECT_EQ(test::json_value(json, "avg_frame_rate"), "30000/1001");
  EXPECT_EQ(test::json_value(json, "nb_read_frames"), "30");
  EXPECT_EQ(test::json_value(json, "duration", "format"), "1.001000");
}

TEST(VideoWriter, FrameRangeMayStartAnywhereButMustBeConsecutive) {
  const fs::path dir = scratch_dir();
  const fs::path file = write_clip(dir / "range.mp4", small_settings(), 15, 100);
  const std::string json = test::ffprobe_json(file);
  EXPECT_EQ(test::json_value(json, "start_time", "format"), "0.000000");
  EXPECT_EQ(test::json_value(json, "duration", "format"), "0.500000");

  VideoSettings s = small_settings();
  VideoWriter writer(dir / "gap.mp4", s);
  writer.write(moving_frame(s.width, s.height, 0), 7);
  EXPECT_EQ(code_of([&] { writer.write(moving_frame(s.width, s.height, 2), 9); }), ExitCode::kInternal);
  EXPECT_EQ(code_of([&] { writer.write(moving_frame(s.width, s.height, 0), 7); }), ExitCode::kInternal);
  EXPECT_EQ(code_of([&] { writer.write(Image(s.width + 2, s.height), 8); }), ExitCode::kInternal);
  writer.write(moving_frame(s.width, s.height, 1), 8);  // The writer is still usable.
  writer.finish();
  EXPECT_EQ(code_of([&] { writer.write(moving_frame(s.width, s.height, 2), 9); }), ExitCode::kInternal);
  EXPECT_EQ(test::json_value(test::ffprobe_json(dir / "gap.mp4"), "nb_read_frames"), "2");
}

TEST(VideoWriter, OddSizeIsRejectedWithTheNearestEvenSizes) {
  const fs::path dir = scratch_dir();
  VideoSettings s;
  s.width = 1281;
  s.height = 720;
  try {
    VideoWriter writer(dir / "odd.mp4", s);
    FAIL() << "odd width accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_STREQ(e.what(), "H.264 in yuv420p needs even sizes: 1281x720 is odd; use 1280x720 or 1282x720");
  }
  s.width = 640;
  s.height = 479;
  EXPECT_EQ(code_of([&] { VideoWriter w(dir / "odd.mp4", s); }), ExitCode::kDataError);
  expect_only(dir, {});
}

TEST(VideoWriter, BadSettingsAreDataErrors) {
  const fs::path dir = scratch_dir();
  auto with = [&](auto change) {
    VideoSettings s = small_settings();
    change(s);
    return code_of([&] { VideoWriter w(dir / "bad.mp4", s); });
  };
  EXPECT_EQ(with([](VideoSettings& s) { s.crf = 52; }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.crf = -1; }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.preset = "warpspeed"; }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.fps = 0; }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.fps = std::nan(""); }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.width = 0; }), ExitCode::kDataError);
  EXPECT_EQ(with([](VideoSettings& s) { s.threads = -2; }), ExitCode::kDataError);
  expect_only(dir, {});
}

TEST(VideoWriter, MissingFolderCannotBeCreated) {
  const fs::path dir = scratch_dir();
  EXPECT_EQ(code_of([&] { VideoWriter w(dir / "no" / "such" / "clip.mp4", small_settings()); }),
            ExitCode::kCannotCreate);
}

TEST(VideoWriter, DestroyedWithoutFinishLeavesEarlierOutputUntouched) {
  const fs::path dir = scratch_dir();
  const fs::path file = dir / "clip.mp4";
  const std::string earlier = "earlier output, not an MP4\n";
  test::write_bytes(file, earlier);
  {
    const VideoSettings s = small_settings();
    VideoWriter writer(file, s);
    for (int i = 0; i < 10; ++i) writer.write(moving_frame(s.width, s.height, i), i);
    int partial = 0;  // The temporary exists while writing; the target is still the old file.
    for (const auto& entry : fs::directory_iterator(dir)) {
      partial += entry.path().filename().string().starts_with(".clip.mp4.partial-") ? 1 : 0;
    }
    EXPECT_EQ(partial, 1);
    EXPECT_EQ(test::read_bytes(file), earlier);
  }
  EXPECT_EQ(test::read_bytes(file), earlier);
  expect_only(dir, {"clip.mp4"});

  const fs::path fresh = dir / "fresh.mp4";
  { VideoWriter writer(fresh, small_settings()); }
  EXPECT_FALSE(fs::exists(fresh));
  expect_only(dir, {"clip.mp4"});
  // No frames: finish refuses, and nothing appears.
  {
    VideoWriter writer(fresh, small_settings());
    EXPECT_EQ(code_of([&] { writer.finish(); }), ExitCode::kInternal);
  }
  expect_only(dir, {"clip.mp4"});
}

TEST(VideoWriter, FinishReplacesEarlierOutput) {
  const fs::path dir = scratch_dir();
  const fs::path file = dir / "clip.mp4";
  test::write_bytes(file, "old");
  write_clip(file, small_settings(), 5);
  EXPECT_EQ(test::json_value(test::ffprobe_json(file), "nb_read_frames"), "5");
  expect_only(dir, {"clip.mp4"});
}

}  // namespace
}  // namespace systole::encode
