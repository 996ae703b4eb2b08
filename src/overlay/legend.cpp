#include "overlay/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/error.h"

namespace systole::overlay {
namespace {

/// Rows of a legend: a swatch of side `size`, a gap, the name; `pad` around it all.
struct LegendMetrics {
  int size, row, pad, gap;
  explicit LegendMetrics(int font_px)
      : size(font_px), row(static_cast<int>(std::lround(1.5 * font_px))), pad(std::max(3, font_px / 2)),
        gap(std::max(3, font_px / 2)) {}
};

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return text;
}

}  // namespace

Rect legend_size(const std::vector<LegendEntry>& entries, plot::Font& font) {
  const LegendMetrics m(font.size());
  double w = 0;
  for (const auto& e : entries) w = std::max(w, font.width(e.name));
  return {0, 0, 2 * m.pad + m.size + m.gap + static_cast<int>(std::ceil(w)),
          2 * m.pad + m.row * static_cast<int>(entries.size())};
}

void swatch_center(const Rect& box, int i, const plot::Font& font, double& x, double& y) {
  const LegendMetrics m(font.size());
  x = box.x + m.pad + 0.5 * m.size;
  y = box.y + m.pad + m.row * (i + 0.5);
}

void draw_legend(Image& image, const Rect& box, const std::vector<LegendEntry>& entries, plot::Font& font,
                 const Style& style) {
  plot::Canvas canvas(image);
  const LegendMetrics m(font.size());
  canvas.fill(box.x, box.y, box.right(), box.bottom(), style.panel, style.panel_alpha);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    double cx = 0, cy = 0;
    swatch_center(box, static_cast<int>(i), font, cx, cy);
    const int x0 = static_cast<int>(std::lround(cx - 0.5 * m.size)), y0 = static_cast<int>(std::lround(cy - 0.5 * m.size));
    canvas.fill(x0 - 1, y0 - 1, x0 + m.size + 1, y0 + m.size + 1, style.ink, 0.9);  // A light rim: dark swatches show.
    canvas.fill(x0, y0, x0 + m.size, y0 + m.size, entries[i].color);
    font.draw(canvas, entries[i].name, x0 + m.size + m.gap, cy + 0.5 * (font.ascent() * 0.75), style.ink);
  }
}

Rgb color_at(const ColorBar& bar, double value) {
  if (bar.colors.size() < 2 || !(bar.max > bar.min)) {
    throw Error(ExitCode::kInternal, "colour bar '" + bar.label + "' needs at least 2 colours and max > min");
  }
  const double f = std::clamp((value - bar.min) / (bar.max - bar.min), 0.0, 1.0) * double(bar.colors.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(f), bar.colors.size() - 2);
  const double u = f - double(i);
  Rgb c{};
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<std::uint8_t>(std::lround(bar.colors[i][k] + u * (double(bar.colors[i + 1][k]) - bar.colors[i][k])));
  }
  return c;
}

void draw_color_bar(Image& image, const Rect& box, const ColorBar& bar, plot::Font& font, const Style& style,
                    Rect* gradient) {
  plot::Canvas canvas(image);
  const int pad = std::max(3, font.size() / 2);
  canvas.fill(box.x, box.y, box.right(), box.bottom(), style.panel, style.panel_alpha);
  const std::string title = bar.unit.empty() ? bar.label : bar.label + " (" + bar.unit + ")";
  font.draw(canvas, title, box.x + pad, box.y + pad + font.ascent() * 0.8, style.ink);
  const int top = box.y + 2 * pad + static_cast<int>(std::ceil(font.ascent())), bottom = box.bottom() - pad;
  const int x0 = box.x + pad, x1 = x0 + std::max(6, font.size());
  const Rect g{x0, top, x1 - x0, std::max(1, bottom - top)};
  for (int y = g.y; y < g.bottom(); ++y) {
    // Row centres map linearly: the bottom row shows min, the top row max.
    const double f = g.height > 1 ? double(g.bottom() - 1 - y) / (g.height - 1) : 0.0;
    canvas.fill(g.x, y, g.right(), y + 1, color_at(bar, bar.min + f * (bar.max - bar.min)));
  }
  for (double f : {0.0, 0.5, 1.0}) {
    const double y = g.bottom() - 0.5 - f * (g.height - 1);
    canvas.line(g.right(), y, g.right() + 4, y, style.ink, 1);
    font.draw(canvas, number_text(bar.min + f * (bar.max - bar.min)), g.right() + 7, y + 0.4 * font.ascent(), style.ink);
  }
  if (gradient) *gradient = g;
}

}  // namespace systole::overlay
