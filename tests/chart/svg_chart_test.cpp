// The SVG chart: every series a polyline in its colour, ticks from the shared axis routine.

#include <gtest/gtest.h>

#include "chart/axis.h"
#include "chart/svg_chart.h"

namespace systole::chart {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgChart, EachSeriesIsAPolylineInItsColourWithTheSharedTicks) {
  const std::vector<double> x = {0, 1, 2, 3, 4};
  const std::string svg = svg_line_chart("title <&>", "time [s]", "size", x,
                                         {{"target", "#112233", false, {0, 1, 0, 1, 0}},
                                          {"played", "#445566", true, {0.5, 0.5, 0.5, 0.5, 0.5}}});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "<polyline"), 2u);
  EXPECT_NE(svg.find("stroke=\"#112233\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos) << "the dashed series";
  EXPECT_NE(svg.find("title &lt;&amp;&gt;"), std::string::npos) << "text is escaped";
  // The x axis shows exactly the ticks chart::ticks gives for its range.
  for (double t : ticks(Axis{"", Scale::kLinear, 0, 4})) {
    EXPECT_NE(svg.find(">" + tick_text(t) + "</text>"), std::string::npos) << t;
  }
}

}  // namespace
}  // namespace systole::chart
