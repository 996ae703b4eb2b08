#include "overlay/title.h"

#include <algorithm>
#include <cmath>

namespace systole::overlay {

Rect draw_title(Image& image, const Rect& rect, const std::string& text, plot::Font& font, int size_px,
                const Style& style) {
  font.size(size_px > 0 ? size_px : std::max(10, rect.height / 24));
  const double w = font.width(text), halo = std::ceil(font.size() / 8.0);
  const double x = rect.x + 0.5 * (rect.width - w), baseline = rect.y + 0.5 * font.size() + font.ascent();
  plot::Canvas canvas(image);
  font.draw_with_halo(canvas, text, x, baseline, style.ink, style.halo, halo, style.halo_alpha);
  return Rect{int(std::floor(x - halo)), int(std::floor(baseline - font.ascent() - halo)), int(std::ceil(w + 2 * halo)),
              int(std::ceil(font.ascent() + font.descent() + 2 * halo))};
}

Rect draw_title(Image& image, const Rect& rect, const std::string& text, int size_px) {
  plot::Font font;
  return draw_title(image, rect, text, font, size_px);
}

}  // namespace systole::overlay
