#pragma once
// Keys to the colours of a frame: a legend of region colours (a swatch and a name per
// region) and a colour bar for a scalar colour map (strain, activation) with its range
// and unit. Both sit on a translucent dark panel with light text.

#include <string>
#include <vector>

#include "common/image.h"
#include "overlay/layout.h"

namespace systole::overlay {

struct LegendEntry {
  std::string name;
  Rgb color{};  ///< The swatch, exactly as given (sRGB).
};

/// The size a legend of `entries` takes with `font` at its current size. unit: px
Rect legend_size(const std::vector<LegendEntry>& entries, plot::Font& font);

/// Draws the legend in `box` (from legend_size, moved into place). Swatch i is a square
/// of side font.size() whose centre is swatch_center(box, i, font).
void draw_legend(Image& image, const Rect& box, const std::vector<LegendEntry>& entries, plot::Font& font,
                 const Style& style = {});
/// Centre of swatch `i` of a legend drawn in `box`. unit: px
void swatch_center(const Rect& box, int i, const plot::Font& font, double& x, double& y);

/// A scalar colour map's key. The renderer's colour map gives the colours, sampled evenly
/// from `min` to `max` (at least 2; interpolated linearly between samples), so the bar
/// shows exactly what the organ is painted with.
struct ColorBar {
  std::string label;      ///< What is mapped: "strain".
  std::string unit;       ///< Shown after the label in brackets: "%"; empty: none.
  double min = 0, max = 1;  ///< The mapped range, in `unit`.
  std::vector<Rgb> colors;  ///< colors.front() at min, colors.back() at max.
};

/// The colour the bar shows at `value` (clamped to [min, max]).
Rgb color_at(const ColorBar& bar, double value);

/// Draws a vertical colour bar in `box`: the label and unit on top, the gradient below
/// it with max at the top and min at the bottom, and tick labels for min, middle and max
/// on its right. `gradient` receives where the gradient itself went.
void draw_color_bar(Image& image, const Rect& box, const ColorBar& bar, plot::Font& font, const Style& style = {},
                    Rect* gradient = nullptr);

}  // namespace systole::overlay
