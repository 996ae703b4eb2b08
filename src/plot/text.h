#pragma once
// Drawing into a systole::Image with coverage blending, and text set with FreeType in
// DejaVu Sans (Debian's fonts-dejavu-core): shared by the charts (plot.h) and the teaching
// overlays (overlay/). Deterministic: the same calls give the same bytes.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/image.h"

struct FT_LibraryRec_;
struct FT_FaceRec_;

namespace systole::plot {

using Rgb = std::array<std::uint8_t, 3>;

/// Coverage in [0, 1] per pixel of a rectangle of the image (text before it is blended).
struct Mask {
  int x0 = 0, y0 = 0;         ///< Top-left pixel in the image. unit: px
  int width = 0, height = 0;  ///< unit: px
  std::vector<float> coverage;  ///< width * height, rows top to bottom. unit: 1

  float at(int x, int y) const { return coverage[static_cast<std::size_t>(y) * width + x]; }
  /// The same mask grown by `radius_px` (a soft-edged disc), for a halo around glyphs.
  Mask dilated(double radius_px) const;
};

/// An image with blending: every drawing call takes a coverage in [0, 1] per pixel.
class Canvas {
 public:
  explicit Canvas(Image& image) : image_(image) {}

  Image& image() { return image_; }
  void blend(int x, int y, const Rgb& c, double coverage);
  /// Antialiased segment of the given width: coverage from the distance to the segment. unit: px
  void line(double x0, double y0, double x1, double y1, const Rgb& c, double width);
  /// Fills [x0, x1) x [y0, y1) with `c` at opacity `alpha`.
  void fill(int x0, int y0, int x1, int y1, const Rgb& c, double alpha = 1.0);
  /// Blends `c` where the mask covers, scaled by `alpha`.
  void blend_mask(const Mask& mask, const Rgb& c, double alpha = 1.0);

 private:
  Image& image_;
};

/// DejaVu Sans through FreeType, at one pixel size at a time; rendered glyphs are cached,
/// so a Font kept across frames sets each glyph once. Text is UTF-8.
class Font {
 public:
  /// Throws Error(kNoInput) when the font is not installed.
  Font();
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  void size(int px);
  int size() const { return size_px_; }
  /// Advance width of `text`. unit: px
  double width(const std::string& text);
  /// Height above the baseline of capitals and below it of descenders. unit: px
  double ascent() const;
  double descent() const;

  /// Draws `text` with its baseline starting at (x, y); `vertical` turns it a quarter
  /// turn counter-clockwise (reading upwards), starting at (x, y); `opacity` in [0, 1]
  /// scales the glyphs' coverage (fading captions).
  void draw(Canvas& canvas, const std::string& text, double x, double y, const Rgb& color, bool vertical = false,
            double opacity = 1.0);
  /// The coverage `draw` would blend (horizontal text), in a mask `pad_px` larger on every side.
  Mask mask(const std::string& text, double x, double y, int pad_px = 0);
  /// Text in `color` over a halo of `halo` (opacity `halo_alpha`) `halo_px` wide around
  /// every glyph, so it reads on dark and light backgrounds alike.
  void draw_with_halo(Canvas& canvas, const std::string& text, double x, double y, const Rgb& color, const Rgb& halo,
                      double halo_px, double halo_alpha = 0.85);

 private:
  struct Glyph {
    int left = 0, top = 0, width = 0, rows = 0;
    double advance = 0;  ///< unit: px
    std::vector<std::uint8_t> bitmap;
  };
  const Glyph& glyph(char32_t code);

  FT_LibraryRec_* library_ = nullptr;
  FT_FaceRec_* face_ = nullptr;
  int size_px_ = 0;
  std::map<std::pair<int, char32_t>, Glyph> cache_;
};

/// The code points of UTF-8 text; a malformed byte reads as U+FFFD.
std::u32string decode_utf8(const std::string& text);

}  // namespace systole::plot
