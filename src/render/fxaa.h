#pragma once
// Fast approximate anti-aliasing on the CPU, after T. Lottes, "FXAA" (NVIDIA white paper,
// 2009), the compact "PC console" variant: where the local luma contrast is high, blur
// along the edge (across the luma gradient) with two or four bilinear taps, keeping the
// four-tap result only if it stays within the local luma range.
//
// Why on the CPU: on llvmpipe 4x MSAA costs 2.2x the draw plus a resolve (about 47 ms of
// CPU per 720p heart frame against 17 ms without), and the same filter as a GLSL pass cost
// more than MSAA (llvmpipe's texture sampler); here flat pixels - most of a frame - stop
// after five luma reads. Figures: docs/performance.md.

#include <cstdint>
#include <vector>

#include "common/image.h"

namespace systole::render {

class Fxaa {
 public:
  /// Smooths the edges of `image` (sRGB, top row first) in place. The result depends only
  /// on the pixels (same bits on every run and thread); no allocation once sized.
  void apply(Image& image);

 private:
  /// The pixels filtered, inclusive bounds, top-left origin. unit: px
  struct Box {
    int xa = 0, xb = -1, ya = 0, yb = -1;
  };
  /// The box of the pixels that differ from the first one, grown by one, without the
  /// frame's border; false when there is nothing to filter.
  bool filtered_box(const Image& image, Box& box);
  /// Copies the rows the taps can read into source_, and fills luma_ over the box grown by one.
  void prepare_source(const Image& image, const Box& box);
  /// Filters row y of `image` from column xa to xb (inclusive).
  void filter_row(Image& image, int y, int xa, int xb);

  std::vector<float> luma_;  ///< Per pixel of the input, unit: 1 (0..1).
  /// Per pixel of the row being filtered: 1 where the contrast is enough to filter. Not a
  /// char: a char store may alias the luma, which kept the compiler from vectorizing the test.
  std::vector<std::uint32_t> edge_;
  std::vector<std::uint8_t> background_;  ///< A row of the frame's first pixel's colour.
  Image source_;             ///< The input, read while `image` is written.
};

}  // namespace systole::render
