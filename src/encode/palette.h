#pragma once
// One palette for a whole clip, and frames reduced to it: what a GIF needs. Median cut
// (Heckbert 1982) over a histogram of every frame's colours, then each pixel maps to the
// nearest palette colour after an 8x8 ordered (Bayer) dither. A global palette and an
// ordered dither keep a still pixel the same index in every frame: no palette flicker and
// no crawling dither noise, so a loop stays calm and the GIF's frame differences stay
// small (docs/teaching-visuals.md says why not Floyd-Steinberg or a palette per frame).

#include <array>
#include <cstdint>
#include <vector>

#include "common/image.h"

namespace systole::encode {

using PaletteColor = std::array<std::uint8_t, 3>;

/// Counts colours over any number of frames, then builds the palette.
class PaletteBuilder {
 public:
  PaletteBuilder();
  /// Adds every pixel of `image` to the histogram (6 bits per channel, with the exact
  /// colours' sums kept so a palette entry is the mean of the colours it stands for).
  void add(const Image& image);
  /// Up to `max_colors` colours (1..256) by median cut; fewer when the frames have fewer.
  std::vector<PaletteColor> build(int max_colors = 256) const;

 private:
  struct Bin {
    std::uint64_t count = 0;
    std::uint64_t sum[3] = {0, 0, 0};
  };
  std::vector<Bin> bins_;  ///< 64^3 bins, index (r >> 2) << 12 | (g >> 2) << 6 | (b >> 2).
};

/// Maps pixels to a palette, with a cache of nearest colours (unit of `dither`: levels of
/// 0..255; 0 turns the dither off).
class PaletteMapper {
 public:
  explicit PaletteMapper(std::vector<PaletteColor> palette, double dither = 12);
  /// Palette indices of `image`, row by row (width * height bytes).
  void map(const Image& image, std::vector<std::uint8_t>& indices);
  const std::vector<PaletteColor>& palette() const { return palette_; }

 private:
  std::uint8_t nearest(int r, int g, int b);
  std::vector<PaletteColor> palette_;
  std::array<int, 64> offset_{};       ///< Bayer 8x8 thresholds as offsets. unit: levels
  std::vector<std::int16_t> cache_;    ///< Nearest index per 6-bit colour; -1: not yet known.
};

}  // namespace systole::encode
