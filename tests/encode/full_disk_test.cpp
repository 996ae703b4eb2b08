// A full disk, for each kind of output: the run fails with the system's reason ("No space
// left on device", not libpng's "Write Error"), naming the file the user asked for (not
// the hidden temporary it was writing), and the earlier output and the folder stay as they
// were. On a 200 KiB tmpfs (root only; skipped with a message elsewhere).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>

#include "common/error.h"
#include "encode/gif_writer.h"
#include "encode/png.h"
#include "encode/video_writer.h"
#include "encode_test_util.h"
#include "support/small_disk.h"

namespace systole::encode {
namespace {

namespace fs = std::filesystem;

/// Noise: no encoder can squeeze it, so a few frames fill the disk.
Image noise(int width, int height, unsigned seed) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    seed = seed * 1664525u + 1013904223u;
    image.rgb[i] = static_cast<std::uint8_t>(seed >> 24);
  }
  return image;
}

/// The message of the Error that `writing` throws (and "" when it throws none).
std::string failure_of(const std::function<void()>& writing) {
  try {
    writing();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kIoError) << e.what();
    return e.what();
  }
  return "";
}

/// The message says why and names `target`, not a temporary.
void expect_told(const std::string& message, const fs::path& target) {
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_NE(message.find("'" + target.string() + "'"), std::string::npos) << message;
  EXPECT_EQ(message.find(".partial"), std::string::npos) << message;
  EXPECT_EQ(message.find(".staging"), std::string::npos) << message;
}

/// The names in `dir`, sorted.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(FullDisk, APngSaysWhyAndNamesItsFile) {
  const systole::test::SmallDisk disk(test::scratch_dir() / "disk", "200k");
  if (!disk.mounted) GTEST_SKIP() << systole::test::kNoSmallDisk;
  test::write_bytes(disk.dir / "x.png", "earlier");
  expect_told(failure_of([&] { write_png(disk.dir / "x.png", noise(512, 512, 1)); }), disk.dir / "x.png");
  EXPECT_EQ(test::read_bytes(disk.dir / "x.png"), "earlier");
  EXPECT_EQ(names_in(disk.dir), std::vector<std::string>{"x.png"});
}

TEST(FullDisk, APngSequenceSaysWhyNamesTheFrameAndLeavesTheFolder) {
  const systole::test::SmallDisk disk(test::scratch_dir() / "disk", "200k");
  if (!disk.mounted) GTEST_SKIP() << systole::test::kNoSmallDisk;
  const fs::path folder = disk.dir / "frames";
  {
    PngSequenceWriter earlier(folder, 10);
    earlier.write(noise(16, 16, 7), 0);
    earlier.finish();
  }
  const std::string frame0 = test::read_bytes(folder / "frame_00000.png");
  std::string message;
  {
    PngSequenceWriter writer(folder, 10);
    message = failure_of([&] {
      for (int i = 0; i < 10; ++i) writer.write(noise(256, 256, 100 + static_cast<unsigned>(i)), i);
    });
  }
  const std::string frame = message.substr(message.find("frame_"), 15);
  expect_told(message, folder / frame);
  EXPECT_EQ(test::read_bytes(folder / "frame_00000.png"), frame0);
  EXPECT_EQ(names_in(folder), std::vector<std::string>{"frame_00000.png"});
  EXPECT_EQ(names_in(disk.dir), std::vector<std::string>{"frames"}) << "no staging folder or lock is left";
}

/// Writes noise frames to `target` with `open`'s writer until it fails.
std::string fill_with(const fs::path& target, const std::function<std::unique_ptr<FrameSink>()>& open) {
  return failure_of([&] {
    const auto sink = open();
    for (int i = 0; i < 40; ++i) sink->write(noise(320, 240, 10 + static_cast<unsigned>(i)), i);
    sink->finish();
  });
}

TEST(FullDisk, AnMkvSaysWhyAndNamesItsFileNotItsTemporary) {
  const systole::test::SmallDisk disk(test::scratch_dir() / "disk", "200k");
  if (!disk.mounted) GTEST_SKIP() << systole::test::kNoSmallDisk;
  const fs::path target = disk.dir / "clip.mkv";
  test::write_bytes(target, "earlier");
  VideoSettings settings;
  settings.format = VideoFormat::kMkv;
  settings.width = 320;
  settings.height = 240;
  expect_told(fill_with(target, [&] { return open_video(target, settings); }), target);
  EXPECT_EQ(test::read_bytes(target), "earlier");
  EXPECT_EQ(names_in(disk.dir), std::vector<std::string>{"clip.mkv"});
}

TEST(FullDisk, AGifSaysWhyAndNamesItsFileNotItsTemporary) {
  const systole::test::SmallDisk disk(test::scratch_dir() / "disk", "200k");
  if (!disk.mounted) GTEST_SKIP() << systole::test::kNoSmallDisk;
  const fs::path target = disk.dir / "clip.gif";
  test::write_bytes(target, "earlier");
  GifSettings settings;
  settings.width = 320;
  settings.height = 240;
  expect_told(fill_with(target, [&] { return std::make_unique<GifWriter>(target, settings); }), target);
  EXPECT_EQ(test::read_bytes(target), "earlier");
  EXPECT_EQ(names_in(disk.dir), std::vector<std::string>{"clip.gif"});
}

}  // namespace
}  // namespace systole::encode
