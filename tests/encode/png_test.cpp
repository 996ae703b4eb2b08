#include "encode/png.h"

#include <gtest/gtest.h>

#include "support/error_code.h"
#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <algorithm>
#include <functional>
#include <iterator>
#include <map>

#include "common/error.h"
#include "encode_test_util.h"

namespace systole::encode {
namespace {

using test::scratch_dir;
namespace fs = std::filesystem;

using systole::test::code_of;

Image pattern(int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * 7 + i / 5);
  return image;
}

// Writes a PNG of any colour type straight through libpng (the code under test writes RGB only).
void write_raw_png(const fs::path& path, int width, int height, int color_type, int bit_depth,
                   const std::vector<std::uint8_t>& bytes, const std::vector<png_color>& palette = {}) {
  FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    FAIL() << "libpng failed writing the test input";
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, width, height, bit_depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  png_write_info(png, info);
  const std::size_t row_bytes = bytes.size() / static_cast<std::size_t>(height);
  for (int y = 0; y < height; ++y) png_write_row(png, bytes.data() + static_cast<std::size_t>(y) * row_bytes);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

TEST(Png, RoundTripIsExact) {
  const fs::path dir = scratch_dir();
  for (auto [w, h] : {std::pair{1, 1}, {3, 5}, {64, 48}, {321, 17}}) {
    const Image image = pattern(w, h);
    write_png(dir / "x.png", image);
    const Image back = read_png(dir / "x.png");
    EXPECT_EQ(back.width, w);
    EXPECT_EQ(back.height, h);
    EXPECT_EQ(back.rgb, image.rgb);
  }
  // Only the file: the temporary was renamed.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(Png, GreyReadsAsRgb) {
  const fs::path dir = scratch_dir();
  const std::vector<std::uint8_t> grey = {0, 50, 100, 150, 200, 255};
  write_raw_png(dir / "grey.png", 3, 2, PNG_COLOR_TYPE_GRAY, 8, grey);
  const Image image = read_png(dir / "grey.png");
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  for (std::size_t i = 0; i < grey.size(); ++i) {
    EXPECT_EQ(image.rgb[3 * i], grey[i]);
    EXPECT_EQ(image.rgb[3 * i + 1], grey[i]);
    EXPECT_EQ(image.rgb[3 * i + 2], grey[i]);
  }
}

TEST(Png, RgbaReadsAsRgbWithAlphaDropped) {
  const fs::path dir = scratch_dir();
  const std::vector<std::uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 10, 20, 30, 40};
  write_raw_png(dir / "rgba.png", 2, 2, PNG_COLOR_TYPE_RGB_ALPHA, 8, rgba);
  const Image image = read_png(dir / "rgba.png");
  ASSERT_EQ(image.rgb.size(), 12u);
  const std::vector<std::uint8_t> want = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
  EXPECT_EQ(image.rgb, want);
}

TEST(Png, SixteenBitGreyAlphaAndPaletteReadAsRgb8) {
  const fs::path dir = scratch_dir();
  // 16-bit grey + alpha, big-endian samples: 0xFFFF, 0x8080 (-> 128), 0x0000.
  const std::vector<std::uint8_t> ga16 = {0xFF, 0xFF, 0xFF, 0xFF, 0x80, 0x80, 0x00, 0x00, 0x00, 0x00, 0xFF, 0xFF};
  write_raw_png(dir / "ga16.png", 3, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 16, ga16);
  const Image ga = read_png(dir / "ga16.png");
  EXPECT_EQ(ga.rgb, (std::vector<std::uint8_t>{255, 255, 255, 128, 128, 128, 0, 0, 0}));

  const std::vector<png_color> palette = {{10, 20, 30}, {200, 100, 50}};
  write_raw_png(dir / "pal.png", 2, 1, PNG_COLOR_TYPE_PALETTE, 8, {1, 0}, palette);
  const Image pal = read_png(dir / "pal.png");
  EXPECT_EQ(pal.rgb, (std::vector<std::uint8_t>{200, 100, 50, 10, 20, 30}));
}

TEST(Png, MissingFileIsNoInput) {
  const fs::path dir = scratch_dir();
  EXPECT_EQ(code_of([&] { read_png(dir / "missing.png"); }), ExitCode::kNoInput);
  EXPECT_EQ(code_of([&] { read_png(dir); }), ExitCode::kNoInput);  // A folder, not a file.
}

TEST(Png, TruncatedAndGarbageFilesAreDataErrors) {
  const fs::path dir = scratch_dir();
  write_png(dir / "good.png", pattern(200, 100));
  const std::string good = test::read_bytes(dir / "good.png");
  // Cut everywhere interesting: inside the signature, the header, the data, before IEND.
  for (std::size_t size : {std::size_t{0}, std::size_t{4}, std::size_t{8}, std::size_t{20}, std::size_t{40},
                           good.size() / 2, good.size() - 13, good.size() - 1}) {
    SCOPED_TRACE("truncated to " + std::to_string(size) + " bytes");
    test::write_bytes(dir / "cut.png", good.substr(0, size));
    if (size == good.size() - 1) {
      // Losing the last CRC byte of IEND: libpng may or may not notice; it must not crash.
      try {
        read_png(dir / "cut.png");
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::kDataError);
      }
      continue;
    }
    EXPECT_EQ(code_of([&] { read_png(dir / "cut.png"); }), ExitCode::kDataError);
  }
  test::write_bytes(dir / "garbage.png", "this is not a PNG at all, just text\n");
  EXPECT_EQ(code_of([&] { read_png(dir / "garbage.png"); }), ExitCode::kDataError);
  // A valid signature followed by noise; then flipped bytes inside the image data.
  std::string noise = good.substr(0, 8);
  for (int i = 0; i < 4000; ++i) noise.push_back(static_cast<char>((i * 2654435761u) >> 13));
  test::write_bytes(dir / "noise.png", noise);
  EXPECT_EQ(code_of([&] { read_png(dir / "noise.png"); }), ExitCode::kDataError);
  std::string flipped = good;
  for (std::size_t i = 60; i < flipped.size() - 20; i += 97) flipped[i] = static_cast<char>(~flipped[i]);
  test::write_bytes(dir / "flipped.png", flipped);
  EXPECT_EQ(code_of([&] { read_png(dir / "flipped.png"); }), ExitCode::kDataError);
}

TEST(Png, HugeDeclaredSizeIsRefused) {
  const fs::path dir = scratch_dir();
  write_png(dir / "good.png", pattern(4, 4));
  std::string bytes = test::read_bytes(dir / "good.png");
  // IHDR width at offset 16: claim 1,000,000 px, with a correct CRC so only the limit
  // (not a checksum) can refuse it before a 12 GB allocation.
  bytes[16] = 0x00, bytes[17] = 0x0F, bytes[18] = 0x42, bytes[19] = 0x40;
  const auto crc = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(bytes.data() + 12), 17));  // "IHDR" + 13 data bytes.
  for (int i = 0; i < 4; ++i) bytes[29 + i] = static_cast<char>(crc >> (24 - 8 * i));
  test::write_bytes(dir / "huge.png", bytes);
  EXPECT_EQ(code_of([&] { read_png(dir / "huge.png"); }), ExitCode::kDataError);
}

TEST(Png, WriteErrors) {
  const fs::path dir = scratch_dir();
  EXPECT_EQ(code_of([&] { write_png(dir / "no" / "x.png", pattern(2, 2)); }), ExitCode::kCannotCreate);
  EXPECT_EQ(code_of([&] { write_png(dir / "empty.png", Image()); }), ExitCode::kInternal);
  Image bad(4, 4);
  bad.rgb.resize(5);
  EXPECT_EQ(code_of([&] { write_png(dir / "bad.png", bad); }), ExitCode::kInternal);
  EXPECT_TRUE(fs::is_empty(dir));
  // Replacing an existing file is atomic: the old one stays until the new one is complete.
  test::write_bytes(dir / "x.png", "old");
  write_png(dir / "x.png", pattern(2, 2));
  EXPECT_EQ(read_png(dir / "x.png").rgb, pattern(2, 2).rgb);
}

TEST(Png, FrameFileNamesSortInFrameOrder) {
  EXPECT_EQ(frame_file_name(0, 300), "frame_00000.png");
  EXPECT_EQ(frame_file_name(42, 300), "frame_00042.png");
  EXPECT_EQ(frame_file_name(99999, 100000), "frame_99999.png");
  EXPECT_EQ(frame_file_name(5, 100001), "frame_000005.png");
  EXPECT_EQ(frame_file_name(1234567, 2000000), "frame_1234567.png");
  std::vector<std::string> names;
  for (int i = 0; i < 1200; i += 7) names.push_back(frame_file_name(i, 1200));
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(code_of([] { frame_file_name(-1, 10); }), ExitCode::kInternal);
}

TEST(Png, SequenceWriterCreatesTheFolderAndNumbersFrames) {
  const fs::path root = scratch_dir();
  const fs::path dir = root / "frames" / "run1";
  PngSequenceWriter writer(dir, 3);
  for (int i = 0; i < 3; ++i) writer.write(pattern(8, 6 + i), i);
  writer.finish();
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png"}));
  EXPECT_EQ(read_png(dir / "frame_00002.png").rgb, pattern(8, 8).rgb);

  test::write_bytes(root / "file", "x");
  EXPECT_EQ(code_of([&] { PngSequenceWriter w(root / "file", 3); }), ExitCode::kCannotCreate);
  EXPECT_EQ(code_of([&] { PngSequenceWriter w(root / "file" / "sub", 3); }), ExitCode::kCannotCreate);
}

/// Every file in `dir` with its bytes, by name.
std::map<std::string, std::string> files_in(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) files[entry.path().filename().string()] = test::read_bytes(entry.path());
  return files;
}

TEST(Png, ASequenceReplacesItsFramesOnlyWhenFinishedAndLeavesTheOthers) {
  const fs::path root = scratch_dir();
  const fs::path dir = root / "frames";
  {
    PngSequenceWriter earlier(dir, 4);
    for (int i = 0; i < 4; ++i) earlier.write(pattern(8, 6 + i), i);
    earlier.finish();
  }
  test::write_bytes(dir / "notes.txt", "mine");
  const auto before = files_in(dir);
  {
    PngSequenceWriter unfinished(dir, 4);  // An error or an interrupt: finish() is never called.
    for (int i = 0; i < 4; ++i) unfinished.write(pattern(5, 5), i);
    EXPECT_EQ(files_in(dir), before) << "nothing lands before finish()";
  }
  EXPECT_EQ(files_in(dir), before);
  {
    PngSequenceWriter selection(dir, 4);  // A --frames selection: frames 1 and 3.
    selection.write(pattern(5, 5), 1);
    selection.write(pattern(5, 5), 3);
    selection.finish();
  }
  auto after = before;
  for (int i : {1, 3}) after[frame_file_name(i, 4)] = test::read_bytes(dir / frame_file_name(i, 4));
  EXPECT_EQ(files_in(dir), after) << "frames 0 and 2 and the note stay";
  EXPECT_EQ(read_png(dir / frame_file_name(3, 4)).rgb, pattern(5, 5).rgb);
  EXPECT_EQ(fs::directory_iterator(root)->path().filename(), "frames");
  EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 1) << "no staging folder or lock is left";
}

}  // namespace
}  // namespace systole::encode
