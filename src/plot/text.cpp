#include "plot/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/error.h"

namespace systole::plot {
namespace {

constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

Mask Mask::dilated(double radius_px) const {
  const int r = static_cast<int>(std::ceil(radius_px + 0.5));
  Mask out{x0 - r, y0 - r, width + 2 * r, height + 2 * r, {}};
  out.coverage.assign(static_cast<std::size_t>(out.width) * out.height, 0.0f);
  // Weight of each offset: a disc of radius_px with a one-pixel soft edge.
  std::vector<std::pair<std::pair<int, int>, float>> disc;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const double w = std::clamp(radius_px + 0.5 - std::hypot(dx, dy), 0.0, 1.0);
      if (w > 0) disc.push_back({{dx, dy}, static_cast<float>(w)});
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float c = at(x, y);
      if (c <= 0) continue;
      for (const auto& [d, w] : disc) {
        float& o = out.coverage[static_cast<std::size_t>(y + r + d.second) * out.width + (x + r + d.first)];
        o = std::max(o, c * w);
      }
    }
  }
  return out;
}

void Canvas::blend(int x, int y, const Rgb& c, double coverage) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0) return;
  const double a = std::min(1.0, coverage);
  std::uint8_t* p = image_.row(y) + 3 * static_cast<std::size_t>(x);
  // The blend lies in [0, 255]: adding 0.5 and truncating rounds it (cheaper than lround).
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(p[k] + a * (c[k] - p[k]) + 0.5);
}

void Canvas::line(double x0, double y0, double x1, double y1, const Rgb& c, double width) {
  const double r = 0.5 * width;
  const int xa = int(std::floor(std::min(x0, x1) - r - 1)), xb = int(std::ceil(std::max(x0, x1) + r + 1));
  const int ya = int(std::floor(std::min(y0, y1) - r - 1)), yb = int(std::ceil(std::max(y0, y1) + r + 1));
  const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
  for (int y = std::max(ya, 0); y <= std::min(yb, image_.height - 1); ++y) {
    for (int x = std::max(xa, 0); x <= std::min(xb, image_.width - 1); ++x) {
      const double px = x + 0.5 - x0, py = y + 0.5 - y0;
      const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
      const double ex = px - t * dx, ey = py - t * dy, d2 = ex * ex + ey * ey;
      if (d2 >= (r + 0.5) * (r + 0.5)) continue;  // Uncovered: most of the box of a slanted line.
      blend(x, y, c, r + 0.5 - std::sqrt(d2));
    }
  }
}

void Canvas::fill(int x0, int y0, int x1, int y1, const Rgb& c, double alpha) {
  if (alpha <= 0) return;
  // One opacity for every pixel: what blend() computes, looked up (panels are large).
  const double a = std::min(1.0, alpha);
  std::array<std::array<std::uint8_t, 256>, 3> table;
  for (int k = 0; k < 3; ++k) {
    for (int v = 0; v < 256; ++v) table[k][v] = static_cast<std::uint8_t>(v + a * (c[k] - v) + 0.5);
  }
  const int xa = std::max(x0, 0), xb = std::min(x1, image_.width);
  for (int y = std::max(y0, 0); y < std::min(y1, image_.height); ++y) {
    std::uint8_t* p = image_.row(y) + 3 * static_cast<std::size_t>(xa);
    for (int x = xa; x < xb; ++x, p += 3) {
      for (int k = 0; k < 3; ++k) p[k] = table[k][p[k]];
    }
  }
}

void Canvas::blend_mask(const Mask& mask, const Rgb& c, double alpha) {
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) blend(mask.x0 + x, mask.y0 + y, c, alpha * mask.at(x, y));
  }
}

std::u32string decode_utf8(const std::string& text) {
  std::u32string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const int extra = b < 0x80 ? 0 : (b >> 5) == 0x6 ? 1 : (b >> 4) == 0xe ? 2 : (b >> 3) == 0x1e ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= text.size()) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    char32_t code = extra == 0 ? b : b & (0x3f >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      ok = ok && (c >> 6) == 0x2;
      code = (code << 6) | (c & 0x3f);
    }
    out.push_back(ok ? code : U'\uFFFD');
    i += ok ? extra + 1 : 1;
  }
  return out;
}

Font::Font() {
  if (FT_Init_FreeType(&library_) != 0) throw Error(ExitCode::kInternal, "FreeType failed to start");
  if (!std::filesystem::exists(kFontPath) || FT_New_Face(library_, kFontPath, 0, &face_) != 0) {
    FT_Done_FreeType(library_);
    throw Error(ExitCode::kNoInput, std::string("cannot load the font ") + kFontPath +
                                        " (install Debian's fonts-dejavu-core: scripts/install-deps)");
  }
}

Font::~Font() {
  FT_Done_Face(face_);
  FT_Done_FreeType(library_);
}

void Font::size(int px) {
  if (px == size_px_) return;
  size_px_ = px;
  FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(px));
}

double Font::ascent() const { return face_->size->metrics.ascender / 64.0; }
double Font::descent() const { return -face_->size->metrics.descender / 64.0; }

const Font::Glyph& Font::glyph(char32_t code) {
  const auto key = std::make_pair(size_px_, code);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  Glyph g;
  if (FT_Load_Char(face_, code, FT_LOAD_RENDER) == 0) {
    const FT_GlyphSlot s = face_->glyph;
    g.left = s->bitmap_left;
    g.top = s->bitmap_top;
    g.width = static_cast<int>(s->bitmap.width);
    g.rows = static_cast<int>(s->bitmap.rows);
    g.advance = s->advance.x / 64.0;
    g.bitmap.resize(static_cast<std::size_t>(g.width) * g.rows);
    for (int row = 0; row < g.rows; ++row) {
      for (int col = 0; col < g.width; ++col) g.bitmap[row * g.width + col] = s->bitmap.buffer[row * s->bitmap.pitch + col];
    }
  }
  return cache_.emplace(key, std::move(g)).first->second;
}

double Font::width(const std::string& text) {
  double w = 0;
  for (char32_t c : decode_utf8(text)) w += glyph(c).advance;
  return w;
}

void Font::draw(Canvas& canvas, const std::string& text, double x, double y, const Rgb& color, bool vertical,
                double opacity) {
  double pen = 0;
  for (char32_t c : decode_utf8(text)) {
    const Glyph& g = glyph(c);
    for (int row = 0; row < g.rows; ++row) {
      for (int col = 0; col < g.width; ++col) {
        const double coverage = opacity * g.bitmap[row * g.width + col] / 255.0;
        const double u = pen + g.left + col, v = double(row) - g.top;
        if (vertical) {
          canvas.blend(int(std::lround(x + v)), int(std::lround(y - u)), color, coverage);
        } else {
          canvas.blend(int(std::lround(x + u)), int(std::lround(y + v)), color, coverage);
        }
      }
    }
    pen += g.advance;
  }
}

Mask Font::mask(const std::string& text, double x, double y, int pad_px) {
  const int x0 = int(std::floor(x)) - pad_px - 2, y0 = int(std::floor(y - ascent())) - pad_px - 2;
  Mask m{x0, y0, int(std::ceil(width(text))) + 2 * pad_px + 6, int(std::ceil(ascent() + descent())) + 2 * pad_px + 6, {}};
  m.coverage.assign(static_cast<std::size_t>(m.width) * m.height, 0.0f);
  double pen = 0;
  for (char32_t c : decode_utf8(text)) {
    const Glyph& g = glyph(c);
    for (int row = 0; row < g.rows; ++row) {
      for (int col = 0; col < g.width; ++col) {
        const int px = int(std::lround(x + pen + g.left + col)) - x0, py = int(std::lround(y + row - g.top)) - y0;
        if (px < 0 || py < 0 || px >= m.width || py >= m.height) continue;
        float& o = m.coverage[static_cast<std::size_t>(py) * m.width + px];
        o = std::max(o, g.bitmap[row * g.width + col] / 255.0f);
      }
    }
    pen += g.advance;
  }
  return m;
}

void Font::draw_with_halo(Canvas& canvas, const std::string& text, double x, double y, const Rgb& color, const Rgb& halo,
                          double halo_px, double halo_alpha) {
  const Mask glyphs = mask(text, x, y);
  canvas.blend_mask(glyphs.dilated(halo_px), halo, halo_alpha);
  canvas.blend_mask(glyphs, color);
}

}  // namespace systole::plot
