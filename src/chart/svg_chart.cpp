#include "chart/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "chart/axis.h"
#include "common/xml.h"

namespace systole::chart {

std::string svg_line_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                           const std::vector<double>& x, const std::vector<SvgSeries>& series) {
  const double width = 640, height = 360, left = 70, right = 20, top = 40, bottom = 50;
  double x_lo = x.empty() ? 0 : x.front(), x_hi = x.empty() ? 1 : x.back();
  double y_lo = 1e300, y_hi = -1e300;
  for (const SvgSeries& s : series)
    for (double v : s.y)
      if (std::isfinite(v)) y_lo = std::min(y_lo, v), y_hi = std::max(y_hi, v);
  if (y_lo > y_hi) y_lo = 0, y_hi = 1;
  const double pad = std::max(1e-9, 0.08 * (y_hi - y_lo));
  y_lo -= pad, y_hi += pad;
  if (x_hi <= x_lo) x_hi = x_lo + 1;
  auto px = [&](double v) { return left + (v - x_lo) / (x_hi - x_lo) * (width - left - right); };
  auto py = [&](double v) { return height - bottom - (v - y_lo) / (y_hi - y_lo) * (height - top - bottom); };

  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
    << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << xml_text(title) << "</text>\n";
  for (double v : ticks(Axis{x_label, Scale::kLinear, x_lo, x_hi})) {
    o << "<line x1=\"" << px(v) << "\" y1=\"" << top << "\" x2=\"" << px(v) << "\" y2=\"" << height - bottom
      << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << px(v) << "\" y=\"" << height - bottom + 16 << "\" text-anchor=\"middle\">" << tick_text(v) << "</text>\n";
  }
  for (double v : ticks(Axis{y_label, Scale::kLinear, y_lo, y_hi})) {
    o << "<line x1=\"" << left << "\" y1=\"" << py(v) << "\" x2=\"" << width - right << "\" y2=\"" << py(v)
      << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << left - 6 << "\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\">" << tick_text(v) << "</text>\n";
  }
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width - left - right << "\" height=\"" << height - top - bottom
    << "\" fill=\"none\" stroke=\"#444\"/>\n";
  o << "<text x=\"" << (left + width - right) / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\">" << xml_text(x_label) << "</text>\n";
  o << "<text transform=\"translate(16 " << (top + height - bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">" << xml_text(y_label) << "</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const SvgSeries& s = series[k];
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"";
    for (std::size_t i = 0; i < s.y.size() && i < x.size(); ++i) {
      if (std::isfinite(s.y[i])) o << px(x[i]) << "," << py(s.y[i]) << " ";
    }
    o << "\"/>\n";
    const double ly = top + 16 + 16 * double(k);
    o << "<line x1=\"" << left + 10 << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 34 << "\" y2=\"" << ly - 4 << "\" stroke=\"" << s.color
      << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n<text x=\"" << left + 40 << "\" y=\"" << ly << "\">"
      << xml_text(s.name) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace systole::chart
