#pragma once
// Charts drawn by Systole itself (no Python, no plotting package): scatter and line series
// on linear or logarithmic axes, with tick labels, point labels, a title and a legend,
// rasterized into a systole::Image (write it with encode::write_png). Text is set with
// FreeType in DejaVu Sans (Debian's fonts-dejavu-core).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/image.h"

namespace systole::plot {

enum class Scale { kLinear, kLog };

struct Axis {
  std::string label;
  Scale scale = Scale::kLinear;
  double min = 0, max = 0;  ///< The shown range; min >= max: fitted to the data.
};

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

/// Where an axis puts a value: the fraction of the way from its min to its max (log
/// axes in log10). unit: 1
double axis_fraction(const Axis& axis, double value);

/// Tick positions for a range: 1-2-5 steps on linear axes; on log axes decades (with 2 and
/// 5 over at most three decades, every mantissa within one decade).
std::vector<double> ticks(const Axis& axis);

}  // namespace systole::plot
