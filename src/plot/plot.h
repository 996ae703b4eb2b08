#pragma once
// Charts drawn by Systole itself (no Python, no plotting package): scatter and line series
// on linear or logarithmic axes, with tick labels, point labels, a title and a legend,
// rasterized into a systole::Image (write it with encode::write_png). Text is set with
// FreeType in DejaVu Sans (Debian's fonts-dejavu-core).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "chart/axis.h"
#include "common/image.h"

namespace systole::plot {

using chart::Axis;
using chart::Scale;
using chart::axis_fraction;
using chart::ticks;
using chart::tick_text;

enum class Marker { kNone, kCircle, kSquare, kDiamond, kRing };

using Rgb = std::array<std::uint8_t, 3>;

struct Point {
  double x = 0, y = 0;
  std::string label;  ///< Written beside the point; empty: none.
};

struct Series {
  std::string name;  ///< In the legend; empty: not listed.
  Rgb color{40, 90, 160};
  Marker marker = Marker::kCircle;
  bool line = false;  ///< Join the points in order.
  double marker_px = 9;  ///< Marker diameter. unit: px
  std::vector<Point> points;
};

struct Figure {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  int width = 1200, height = 800;  ///< unit: px
};

/// Draws the figure. Throws Error(kDataError) when a log axis meets a value <= 0 or a
/// value is not finite, and Error(kNoInput) when the font is not installed.
Image render(const Figure& figure);

}  // namespace systole::plot
