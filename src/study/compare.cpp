#include "study/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "common/error.h"

namespace systole::study {
namespace {

void require_same_size(const Image& actual, const Image& reference) {
  if (actual.width == reference.width && actual.height == reference.height) return;
  throw Error(ExitCode::kDataError, "the images differ in size: actual " + std::to_string(actual.width) + "x" +
                                        std::to_string(actual.height) + ", reference " +
                                        std::to_string(reference.width) + "x" + std::to_string(reference.height));
}

}  // namespace

Comparison compare_images(const Image& actual, const Image& reference, const CompareTolerance& tolerance) {
  require_same_size(actual, reference);
  Comparison c;
  c.pixel_count = static_cast<long long>(actual.width) * actual.height;
  double squared_sum = 0;
  for (long long p = 0; p < c.pixel_count; ++p) {
    int pixel_delta = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int d = std::abs(int{actual.rgb[3 * p + ch]} - int{reference.rgb[3 * p + ch]});
      pixel_delta = std::max(pixel_delta, d);
      squared_sum += double(d) * d;
    }
    c.max_delta = std::max(c.max_delta, pixel_delta);
    if (pixel_delta > tolerance.max_delta) ++c.pixels_over;
  }
  c.percent_over = c.pixel_count > 0 ? 100.0 * double(c.pixels_over) / double(c.pixel_count) : 0.0;
  const double mse = c.pixel_count > 0 ? squared_sum / (3.0 * double(c.pixel_count)) : 0.0;
  c.psnr_db = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  c.passed = c.percent_over <= tolerance.max_percent;
  return c;
}

std::string describe(const Comparison& c, const CompareTolerance& t) {
  char text[512];
  const char* verdict = c.max_delta == 0 ? "same" : c.passed ? "within tolerance" : "differs";
  char psnr[32];
  if (std::isinf(c.psnr_db)) {
    std::snprintf(psnr, sizeof psnr, "inf");
  } else {
    std::snprintf(psnr, sizeof psnr, "%.2f dB", c.psnr_db);
  }
  std::snprintf(text, sizeof text,
                "max delta %d (tolerance %d)\n"
                "pixels over %lld of %lld = %.4f%% (tolerance %g%%)\n"
                "psnr %s\n"
                "%s\n",
                c.max_delta, t.max_delta, c.pixels_over, c.pixel_count, c.percent_over, t.max_percent, psnr, verdict);
  return text;
}

Image difference_image(const Image& actual, const Image& reference) {
  require_same_size(actual, reference);
  const int w = actual.width;
  int largest = 0;
  for (std::size_t i = 0; i < actual.rgb.size(); ++i) {
    largest = std::max(largest, std::abs(int{actual.rgb[i]} - int{reference.rgb[i]}));
  }
  const double gain = largest > 0 ? 255.0 / largest : 1.0;
  Image out(3 * w, actual.height);
  for (int y = 0; y < actual.height; ++y) {
    std::uint8_t* row = out.row(y);
    const std::uint8_t* a = actual.row(y);
    const std::uint8_t* r = reference.row(y);
    std::copy(a, a + 3 * w, row);
    std::copy(r, r + 3 * w, row + 3 * w);
    for (int i = 0; i < 3 * w; ++i) {
      const long amplified = std::lround(gain * std::abs(int{a[i]} - int{r[i]}));
      row[6 * w + i] = static_cast<std::uint8_t>(std::min(255L, amplified));
    }
  }
  return out;
}

}  // namespace systole::study
