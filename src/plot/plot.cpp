#include "plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include "common/error.h"
#include "plot/text.h"

namespace systole::plot {
namespace {

/// A marker of diameter `size` centred on (cx, cy). unit: px
void draw_marker(Canvas& canvas, double cx, double cy, Marker m, double size, const Rgb& c) {
  const double r = 0.5 * size;
  for (int y = int(cy - r - 2); y <= int(cy + r + 2); ++y) {
    for (int x = int(cx - r - 2); x <= int(cx + r + 2); ++x) {
      const double px = x + 0.5 - cx, py = y + 0.5 - cy;
      double d = 0;  // Signed distance to the outline, negative inside.
      switch (m) {
        case Marker::kNone: return;
        case Marker::kCircle: d = std::hypot(px, py) - r; break;
        case Marker::kSquare: d = std::max(std::abs(px), std::abs(py)) - 0.8 * r; break;
        case Marker::kDiamond: d = (std::abs(px) + std::abs(py) - 1.2 * r) / std::sqrt(2.0); break;
        case Marker::kRing: d = std::abs(std::hypot(px, py) - r) - 1.0; break;
      }
      canvas.blend(x, y, c, 0.5 - d);
    }
  }
}


/// Fits an axis without a range to the values it shows, with a margin.
Axis fitted(Axis axis, const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v)) throw Error(ExitCode::kDataError, "plot: axis '" + axis.label + "' has a value that is not finite");
    if (axis.scale == Scale::kLog && v <= 0) {
      throw Error(ExitCode::kDataError, "plot: log axis '" + axis.label + "' cannot show " + tick_text(v));
    }
  }
  if (axis.min < axis.max) return axis;
  if (values.empty()) {
    axis.min = axis.scale == Scale::kLog ? 1 : 0;
    axis.max = axis.scale == Scale::kLog ? 10 : 1;
    return axis;
  }
  double lo = *std::min_element(values.begin(), values.end()), hi = *std::max_element(values.begin(), values.end());
  if (axis.scale == Scale::kLog) {
    lo = std::log10(lo);
    hi = std::log10(hi);
  }
  const double margin = hi > lo ? 0.08 * (hi - lo) : 0.5;
  lo -= margin;
  hi += margin;
  axis.min = axis.scale == Scale::kLog ? std::pow(10.0, lo) : lo;
  axis.max = axis.scale == Scale::kLog ? std::pow(10.0, hi) : hi;
  return axis;
}

const Rgb kInk{30, 30, 30};

// The plot area in pixels and the axes it spans.
struct PlotArea {
  Axis x_axis, y_axis;
  int left, right, top, bottom;
  std::pair<double, double> to_px(double x, double y) const {
    return std::pair<double, double>{left + axis_fraction(x_axis, x) * (right - left),
                                     bottom - axis_fraction(y_axis, y) * (bottom - top)};
  }
};

// Grid lines with their tick labels, the axis lines, the axis labels and the title.
void draw_axes(Canvas& canvas, Font& font, const Figure& figure, const PlotArea& area) {
  const Rgb& ink = kInk;
  const Rgb grid{225, 225, 225};
  const Axis& x_axis = area.x_axis;
  const Axis& y_axis = area.y_axis;
  const int left = area.left, right = area.right, top = area.top, bottom = area.bottom;
  auto to_px = [&](double x, double y) { return area.to_px(x, y); };
  font.size(15);
  for (double t : ticks(x_axis)) {
    const double px = to_px(t, y_axis.min).first;
    canvas.line(px, top, px, bottom, grid, 1);
    const std::string text = tick_text(t);
    font.draw(canvas, text, px - font.width(text) / 2, bottom + 22, ink);
  }
  for (double t : ticks(y_axis)) {
    const double py = to_px(x_axis.min, t).second;
    canvas.line(left, py, right, py, grid, 1);
    const std::string text = tick_text(t);
    font.draw(canvas, text, left - 8 - font.width(text), py + 5, ink);
  }
  canvas.line(left, bottom, right, bottom, ink, 1.5);
  canvas.line(left, top, left, bottom, ink, 1.5);

  font.size(17);
  font.draw(canvas, x_axis.label, (left + right) / 2.0 - font.width(x_axis.label) / 2, figure.height - 25, ink);
  font.draw(canvas, y_axis.label, 28, (top + bottom) / 2.0 + font.width(y_axis.label) / 2, ink, true);
  if (!figure.title.empty()) {
    font.size(20);
    font.draw(canvas, figure.title, (left + right) / 2.0 - font.width(figure.title) / 2, 35, ink);
  }
}

// Each series: its line, then its markers with their labels.
void draw_series(Canvas& canvas, Font& font, const Figure& figure, const PlotArea& area) {
  const Rgb& ink = kInk;
  auto to_px = [&](double x, double y) { return area.to_px(x, y); };
  font.size(12);
  for (const auto& s : figure.series) {
    for (std::size_t i = 0; s.line && i + 1 < s.points.size(); ++i) {
      const auto [x0, y0] = to_px(s.points[i].x, s.points[i].y);
      const auto [x1, y1] = to_px(s.points[i + 1].x, s.points[i + 1].y);
      canvas.line(x0, y0, x1, y1, s.color, 2);
    }
    for (const auto& p : s.points) {
      const auto [px, py] = to_px(p.x, p.y);
      draw_marker(canvas, px, py, s.marker, s.marker_px, s.color);
      if (!p.label.empty()) font.draw(canvas, p.label, px + s.marker_px / 2 + 3, py - 3, ink);
    }
  }
}

// Legend, top right: the named series.
void draw_legend(Canvas& canvas, Font& font, const Figure& figure, const PlotArea& area) {
  const Rgb& ink = kInk;
  const int right = area.right, top = area.top;
  std::vector<const Series*> listed;
  for (const auto& s : figure.series) {
    if (!s.name.empty()) listed.push_back(&s);
  }
  if (!listed.empty()) {
    font.size(14);
    double w = 0;
    for (const auto* s : listed) w = std::max(w, font.width(s->name));
    const int row = 22, x0 = right - int(w) - 50, y0 = top + 10;
    canvas.fill(x0, y0, right - 10, y0 + row * int(listed.size()) + 8, Rgb{248, 248, 248});
    for (std::size_t i = 0; i < listed.size(); ++i) {
      const double cy = y0 + 4 + row * (i + 0.5);
      if (listed[i]->line) canvas.line(x0 + 6, cy, x0 + 30, cy, listed[i]->color, 2);
      draw_marker(canvas, x0 + 18, cy, listed[i]->marker, listed[i]->marker_px, listed[i]->color);
      font.draw(canvas, listed[i]->name, x0 + 36, cy + 5, ink);
    }
  }
}

}  // namespace

Image render(const Figure& figure) {
  std::vector<double> xs, ys;
  for (const auto& s : figure.series) {
    for (const auto& p : s.points) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  }
  const Axis x_axis = fitted(figure.x, xs), y_axis = fitted(figure.y, ys);

  Image image(figure.width, figure.height);
  std::fill(image.rgb.begin(), image.rgb.end(), std::uint8_t{255});
  Canvas canvas(image);
  Font font;
  const PlotArea area{x_axis, y_axis, 95, figure.width - 30, figure.title.empty() ? 30 : 60, figure.height - 75};
  draw_axes(canvas, font, figure, area);
  draw_series(canvas, font, figure, area);
  draw_legend(canvas, font, figure, area);
  return image;
}

}  // namespace systole::plot
