#pragma once
// Text set with FreeType in DejaVu Sans (Debian's fonts-dejavu-core): for plots, title
// cards and captions. UTF-8 in; antialiased glyph coverage blended onto an Image.

#include <array>
#include <cstdint>
#include <string>

#include "common/image.h"

typedef struct FT_LibraryRec_* FT_Library;
typedef struct FT_FaceRec_* FT_Face;

namespace systole::plot {

using Rgb = std::array<std::uint8_t, 3>;

/// The font file every text is set in.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// DejaVu Sans through FreeType, at one pixel size at a time.
class Font {
 public:
  /// Throws Error(kNoInput) when the font is not installed.
  Font();
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  /// Sets the size: the em height. unit: px
  void size(int px);
  /// Advance width of `text` (UTF-8) at the current size. unit: px
  double width(const std::string& text);
  /// Ascender minus descender at the current size. unit: px
  double line_height() const;
  /// Ascender above the baseline at the current size. unit: px
  double ascender() const;

  /// Draws `text` (UTF-8) with its baseline starting at (x, y), blending `color` by glyph
  /// coverage times `opacity` (in [0, 1]); `vertical` turns it a quarter turn
  /// counter-clockwise (reading upwards), starting at (x, y).
  void draw(Image& image, const std::string& text, double x, double y, const Rgb& color, double opacity = 1,
            bool vertical = false);

 private:
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
};

/// Blends `color` over the pixel by `alpha` (clamped to [0, 1]); outside the image: nothing.
void blend_pixel(Image& image, int x, int y, const Rgb& color, double alpha);

}  // namespace systole::plot
