// Image comparison on constructed images: the figures, the verdicts, the diff picture, and
// `systole compare`'s exit codes for each case a golden test can meet.

#include "study/compare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "encode/png.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using study::CompareTolerance;

/// A 320x240 gradient, so no two rows look alike.
Image gradient(int w = 320, int h = 240) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.row(y) + 3 * x;
      p[0] = static_cast<std::uint8_t>(x * 255 / w);
      p[1] = static_cast<std::uint8_t>(y * 255 / h);
      p[2] = static_cast<std::uint8_t>(100);
    }
  }
  return img;
}

/// The gradient with pixel (17, 33)'s green channel moved by 200 levels.
Image one_pixel_off() {
  Image img = gradient();
  std::uint8_t* p = img.row(33) + 3 * 17;
  p[1] = static_cast<std::uint8_t>(p[1] + 200);
  return img;
}

/// The gradient with every pixel's blue channel one level up.
Image all_pixels_slightly_off() {
  Image img = gradient();
  for (std::size_t i = 2; i < img.rgb.size(); i += 3) img.rgb[i] += 1;
  return img;
}

TEST(Compare, IdenticalImagesAreTheSame) {
  const auto c = study::compare_images(gradient(), gradient(), {});
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.max_delta, 0);
  EXPECT_EQ(c.pixels_over, 0);
  EXPECT_EQ(c.pixel_count, 320 * 240);
  EXPECT_TRUE(std::isinf(c.psnr_db));
  const auto text = study::describe(c, {});
  EXPECT_NE(text.find("max delta 0"), std::string::npos) << text;
  EXPECT_NE(text.find("psnr inf"), std::string::npos) << text;
  EXPECT_NE(text.find("\nsame\n"), std::string::npos) << text;
}

TEST(Compare, OnePixelFarOffCountsAsOnePixelOver) {
  const auto exact = study::compare_images(one_pixel_off(), gradient(), {});
  EXPECT_FALSE(exact.passed);
  EXPECT_EQ(exact.max_delta, 200);
  EXPECT_EQ(exact.pixels_over, 1);
  EXPECT_DOUBLE_EQ(exact.percent_over, 100.0 / (320 * 240));
  // MSE = 200^2 / (3 * 76800 channels).
  EXPECT_NEAR(exact.psnr_db, 10 * std::log10(255.0 * 255.0 * 3 * 76800 / (200.0 * 200.0)), 1e-9);
  // A large delta passes only when the share of pixels allows it (1 of 76800 = 0.0013%).
  EXPECT_TRUE(study::compare_images(one_pixel_off(), gradient(), {2, 0.01}).passed);
  EXPECT_FALSE(study::compare_images(one_pixel_off(), gradient(), {199, 0.001}).passed);
  EXPECT_TRUE(study::compare_images(one_pixel_off(), gradient(), {200, 0}).passed);
}

TEST(Compare, ManyPixelsSlightlyOffPassOnlyWithADeltaTolerance) {
  const auto exact = study::compare_images(all_pixels_slightly_off(), gradient(), {0, 50});
  EXPECT_FALSE(exact.passed);
  EXPECT_EQ(exact.max_delta, 1);
  EXPECT_EQ(exact.pixels_over, 320 * 240);
  EXPECT_DOUBLE_EQ(exact.percent_over, 100);
  EXPECT_NEAR(exact.psnr_db, 10 * std::log10(255.0 * 255.0 * 3), 1e-9);  // MSE = 1/3
  const auto tolerant = study::compare_images(all_pixels_slightly_off(), gradient(), {1, 0});
  EXPECT_TRUE(tolerant.passed);
  EXPECT_EQ(tolerant.pixels_over, 0);
  EXPECT_NE(study::describe(tolerant, {1, 0}).find("within tolerance"), std::string::npos);
}

TEST(Compare, DifferentSizesAreADataError) {
  try {
    study::compare_images(gradient(320, 240), gradient(320, 200), {});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("actual 320x240, reference 320x200"), std::string::npos) << e.what();
  }
  EXPECT_THROW(study::difference_image(gradient(10, 10), gradient(12, 10)), Error);
}

TEST(Compare, DifferenceImageShowsActualReferenceAndAmplifiedDifference) {
  const Image actual = all_pixels_slightly_off(), reference = gradient();
  const Image diff = study::difference_image(actual, reference);
  ASSERT_EQ(diff.width, 3 * 320);
  ASSERT_EQ(diff.height, 240);
  for (auto [x, y] : {std::pair{0, 0}, {100, 50}, {319, 239}}) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(diff.pixel(x, y)[c], actual.pixel(x, y)[c]);
      EXPECT_EQ(diff.pixel(320 + x, y)[c], reference.pixel(x, y)[c]);
    }
    // A one-level difference is amplified to full scale; equal channels stay black.
    EXPECT_EQ(diff.pixel(640 + x, y)[0], 0);
    EXPECT_EQ(diff.pixel(640 + x, y)[1], 0);
    EXPECT_EQ(diff.pixel(640 + x, y)[2], 255);
  }
}

// --- systole compare --------------------------------------------------------------------

struct Files {
  fs::path reference, same, one_off, slightly_off, smaller, corrupt;
};

Files write_cases(const fs::path& dir) {
  Files f{dir / "reference.png", dir / "same.png",    dir / "one_off.png",
          dir / "slightly_off.png", dir / "smaller.png", dir / "corrupt.png"};
  encode::write_png(f.reference, gradient());
  encode::write_png(f.same, gradient());
  encode::write_png(f.one_off, one_pixel_off());
  encode::write_png(f.slightly_off, all_pixels_slightly_off());
  encode::write_png(f.smaller, gradient(160, 120));
  // A real PNG cut short: the signature and header are fine, the pixel data is missing.
  const std::string bytes = read_file(f.reference);
  write_file(f.corrupt, bytes.substr(0, bytes.size() / 2));
  return f;
}

std::string compare(const fs::path& a, const fs::path& b, const std::string& options = "") {
  return systole() + " compare " + a.string() + " " + b.string() + " " + options;
}

TEST(CompareCommand, IdenticalImagesExitZero) {
  const auto f = write_cases(scratch("compare_same"));
  const auto r = run(compare(f.same, f.reference, "--diff " + (f.same.parent_path() / "diff.png").string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* figure : {"max delta 0", "pixels over 0 of 76800", "psnr inf", "same"}) {
    EXPECT_NE(r.output.find(figure), std::string::npos) << figure << " in:\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(f.same.parent_path() / "diff.png")) << "no diff image when they match";
}

TEST(CompareCommand, OnePixelFarOffDiffersAndWritesTheDiffImage) {
  const auto dir = scratch("compare_one_off");
  const auto f = write_cases(dir);
  const auto r = run(compare(f.one_off, f.reference, "--diff " + (dir / "diff.png").string()));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  for (const char* figure : {"max delta 200", "pixels over 1 of 76800", "psnr 55.7", "differs"}) {
    EXPECT_NE(r.output.find(figure), std::string::npos) << figure << " in:\n" << r.output;
  }
  const Image diff = encode::read_png(dir / "diff.png");
  EXPECT_EQ(diff.width, 960);
  EXPECT_EQ(diff.height, 240);
  EXPECT_EQ(diff.pixel(640 + 17, 33)[1], 255) << "the off pixel, amplified";
  EXPECT_EQ(diff.pixel(640 + 18, 33)[1], 0);
  // Allowed when the tolerance admits one pixel in 76800.
  EXPECT_EQ(run(compare(f.one_off, f.reference, "--max-percent 0.002")).exit_code, 0);
}

TEST(CompareCommand, ManyPixelsSlightlyOffNeedADeltaTolerance) {
  const auto f = write_cases(scratch("compare_slightly_off"));
  const auto strict = run(compare(f.slightly_off, f.reference, "--max-percent 10"));
  EXPECT_EQ(strict.exit_code, 1) << strict.output;
  EXPECT_NE(strict.output.find("pixels over 76800 of 76800 = 100.0000%"), std::string::npos) << strict.output;
  const auto tolerant = run(compare(f.slightly_off, f.reference, "--max-delta 1"));
  EXPECT_EQ(tolerant.exit_code, 0) << tolerant.output;
  EXPECT_NE(tolerant.output.find("within tolerance"), std::string::npos) << tolerant.output;
}

TEST(CompareCommand, DifferentSizesExit65) {
  const auto f = write_cases(scratch("compare_sizes"));
  const auto r = run(compare(f.smaller, f.reference));
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("actual 160x120, reference 320x240"), std::string::npos) << r.output;
}

TEST(CompareCommand, CorruptOrMissingInputIsReportedNotCompared) {
  const auto f = write_cases(scratch("compare_corrupt"));
  const auto corrupt = run(compare(f.corrupt, f.reference));
  EXPECT_EQ(corrupt.exit_code, 65) << corrupt.output;
  EXPECT_NE(corrupt.output.find("corrupt.png"), std::string::npos) << corrupt.output;
  const auto not_png = f.corrupt.parent_path() / "text.png";
  write_file(not_png, "not an image at all");
  EXPECT_EQ(run(compare(f.reference, not_png)).exit_code, 65);
  const auto missing = run(compare(f.reference, f.reference.parent_path() / "nowhere.png"));
  EXPECT_EQ(missing.exit_code, 66) << missing.output;
  EXPECT_NE(missing.output.find("nowhere.png"), std::string::npos) << missing.output;
}

TEST(CompareCommand, ToleranceOutsideItsRangeIsUsage) {
  const auto f = write_cases(scratch("compare_usage"));
  EXPECT_EQ(run(compare(f.same, f.reference, "--max-delta 256")).exit_code, 64);
  EXPECT_EQ(run(compare(f.same, f.reference, "--max-percent -1")).exit_code, 64);
  EXPECT_EQ(run(systole() + " compare " + f.same.string()).exit_code, 64);
}

}  // namespace
}  // namespace systole::test
