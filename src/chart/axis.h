#pragma once
// The axes every chart of Systole shares, whatever draws it (plot/ rasterizes with FreeType
// text, chart/svg_chart.h writes SVG): the range, linear or logarithmic, and one routine
// that picks round tick values. No font and no pixels here, so training's SVG report
// links no FreeType.

#include <string>
#include <vector>

namespace systole::chart {

enum class Scale { kLinear, kLog };

struct Axis {
  std::string label;
  Scale scale = Scale::kLinear;
  double min = 0, max = 0;  ///< The shown range; min >= max: fitted to the data.
};

/// Where an axis puts a value: the fraction of the way from its min to its max (log
/// axes in log10). unit: 1
double axis_fraction(const Axis& axis, double value);

/// Tick positions for a range: 1-2-5 steps on linear axes; on log axes decades (with 2 and
/// 5 over at most three decades, every mantissa within one decade).
std::vector<double> ticks(const Axis& axis);

/// A tick's label: the shortest form of the value ("%g"), with round-off near 0 shown as 0.
std::string tick_text(double value);

}  // namespace systole::chart
