#include "plot/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "common/error.h"

namespace systole::plot {
namespace {

/// Code points of UTF-8 text; a malformed byte stands for itself (Latin-1), so any input draws.
std::vector<char32_t> code_points(const std::string& text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
    char32_t cp = extra == 0 ? b : b & (0x3F >> extra);
    bool ok = i + static_cast<std::size_t>(extra) < text.size();
    for (int k = 1; ok && k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      ok = (c & 0xC0) == 0x80;
      cp = cp << 6 | (c & 0x3F);
    }
    if (!ok) cp = b, i += 1;
    else i += 1 + static_cast<std::size_t>(extra);
    out.push_back(cp);
  }
  return out;
}

}  // namespace

void blend_pixel(Image& image, int x, int y, const Rgb& c, double alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || alpha <= 0) return;
  const double a = std::min(1.0, alpha);
  std::uint8_t* p = image.row(y) + 3 * static_cast<std::size_t>(x);
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(p[k] + a * (c[static_cast<std::size_t>(k)] - p[k])));
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

void Font::size(int px) { FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(std::max(1, px))); }

double Font::width(const std::string& text) {
  double w = 0;
  for (char32_t ch : code_points(text)) {
    if (FT_Load_Char(face_, ch, FT_LOAD_DEFAULT) == 0) w += face_->glyph->advance.x / 64.0;
  }
  return w;
}

double Font::line_height() const { return (face_->size->metrics.ascender - face_->size->metrics.descender) / 64.0; }

double Font::ascender() const { return face_->size->metrics.ascender / 64.0; }

void Font::draw(Image& image, const std::string& text, double x, double y, const Rgb& color, double opacity,
                bool vertical) {
  double pen = 0;
  for (char32_t ch : code_points(text)) {
    if (FT_Load_Char(face_, ch, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = face_->glyph;
    for (unsigned row = 0; row < g->bitmap.rows; ++row) {
      for (unsigned col = 0; col < g->bitmap.width; ++col) {
        const double coverage = g->bitmap.buffer[row * static_cast<unsigned>(g->bitmap.pitch) + col] / 255.0;
        const double u = pen + g->bitmap_left + col, v = double(row) - g->bitmap_top;
        if (vertical) {
          blend_pixel(image, int(std::lround(x + v)), int(std::lround(y - u)), color, coverage * opacity);
        } else {
          blend_pixel(image, int(std::lround(x + u)), int(std::lround(y + v)), color, coverage * opacity);
        }
      }
    }
    pen += g->advance.x / 64.0;
  }
}

}  // namespace systole::plot
