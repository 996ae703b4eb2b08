// ctest-labels: slow-under-sanitizers
// The rendered heart beats at its scene's rate: 90 PNG frames, the silhouette's area as a
// signal, its strongest frequency.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "encode/png.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kHeart = source("scenes/heart.yaml");

/// Pixels that are not background, per frame: the organ's silhouette area.
std::vector<double> silhouette_areas(const fs::path& folder, int frames) {
  std::vector<double> area;
  for (int f = 0; f < frames; ++f) {
    const Image img = encode::read_png(folder / encode::frame_file_name(f, frames));
    const auto* bg = img.pixel(0, 0);
    int count = 0;
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        const auto* p = img.pixel(x, y);
        if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 12) ++count;
      }
    }
    area.push_back(count);
  }
  return area;
}

TEST(Cli, TheHeartBeatsAtItsRate) {
  // 3 s at 72 bpm = 3.6 beats, rendered small; the camera never moves, so any change of
  // the silhouette is the organ's own motion.
  const auto dir = scratch("beat");
  const int frames = 90;
  const auto r = run(systole() + " render " + kHeart +
                     " -D output.width=160 -D output.height=120 -D 'output.duration=3 s' --no-video --png " +
                     (dir / "frames").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto area = silhouette_areas(dir / "frames", frames);
  const auto [lo, hi] = std::minmax_element(area.begin() + 15, area.end());
  EXPECT_GT(*hi / *lo, 1.03) << "the silhouette changes by more than 3% over a beat";

  // The strongest frequency of the area signal after the first beat is the heart rate.
  const int start = 15;
  double mean = 0;
  for (int f = start; f < frames; ++f) mean += area[f] / (frames - start);
  double best_f = 0, best = 0;
  for (double f = 0.4; f <= 5.0; f += 0.1) {
    std::complex<double> sum = 0;
    for (int k = start; k < frames; ++k) sum += (area[k] - mean) * std::polar(1.0, -2 * std::numbers::pi * f * k / 30.0);
    if (std::norm(sum) > best) best = std::norm(sum), best_f = f;
  }
  EXPECT_NEAR(best_f, 1.2, 0.15) << "72 bpm";
}

}  // namespace
}  // namespace systole::test
