#pragma once
// A line chart as SVG text: a few named series over one x axis, with axes, ticks (the same
// as every chart's, chart/axis.h) and a legend. Small on purpose: the training report's
// plots need no more.

#include <string>
#include <vector>

namespace systole::chart {

struct SvgSeries {
  std::string name;
  std::string color;        ///< CSS colour, e.g. "#c0392b".
  bool dashed = false;
  std::vector<double> y;    ///< One value per x.
};

/// The chart of `series` over `x` (every series as long as x), titled, with labelled axes.
std::string svg_line_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                           const std::vector<double>& x, const std::vector<SvgSeries>& series);

}  // namespace systole::chart
