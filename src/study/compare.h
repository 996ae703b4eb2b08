#pragma once
// Golden-image comparison: two RGB images, per channel, with two tolerances - how far a
// channel may be off (max_delta), and what share of the pixels may be off by more
// (max_percent). Rasterizers differ in the odd edge pixel, so a count of "pixels over" is a
// better test than a mean: a moved silhouette fails it even when the mean barely moves.
//
// Inputs:  actual and reference images of the same size; tolerances.
// Outputs: the figures (max delta, pixels over, PSNR) and the verdict; on request a
//          side-by-side picture actual | reference | amplified difference.
// See also: cli/compare_command.cpp, tests/golden/, docs/golden-images.md.

#include <string>

#include "common/image.h"

namespace systole::study {

struct CompareTolerance {
  int max_delta = 0;        ///< A pixel is "over" when a channel differs by more. unit: 8-bit levels
  double max_percent = 0;   ///< Share of pixels allowed over max_delta. unit: % of the pixels
};

struct Comparison {
  int max_delta = 0;             ///< Largest difference in any channel of any pixel. unit: 8-bit levels
  long long pixels_over = 0;     ///< Pixels with a channel differing by more than the tolerance.
  long long pixel_count = 0;
  double percent_over = 0;       ///< unit: % of the pixels
  double psnr_db = 0;            ///< Peak signal-to-noise ratio over all channels; +inf when equal. unit: dB
  bool passed = false;           ///< percent_over <= tolerance.max_percent
};

/// Compares per channel. Throws Error(kDataError) when the sizes differ (naming both).
Comparison compare_images(const Image& actual, const Image& reference, const CompareTolerance& tolerance);

/// The figures, one per line: "max delta ...", "pixels over ...", "psnr ...", then
/// "same", "within tolerance" or "differs".
std::string describe(const Comparison& c, const CompareTolerance& tolerance);

/// actual | reference | difference, side by side (3 widths x 1 height). The difference is
/// |actual - reference| per channel, amplified so the largest difference is full scale
/// (255), so a one-level change is still visible. Sizes must match (kDataError).
Image difference_image(const Image& actual, const Image& reference);

}  // namespace systole::study
