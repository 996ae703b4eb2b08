#pragma once
// Screen rectangles and corners for the teaching overlays (labels, legend, colour bar,
// trace insets, titles), and the look they share: light text on a dark halo or panel, so
// each reads on dark and light backgrounds alike.

#include <algorithm>

#include "plot/text.h"

namespace systole::overlay {

using plot::Rgb;

/// A rectangle of pixels: [x, x + width) x [y, y + height), y down. unit: px
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;

  int right() const { return x + width; }
  int bottom() const { return y + height; }
  bool contains(double px, double py) const { return px >= x && px < right() && py >= y && py < bottom(); }
  bool overlaps(const Rect& o) const { return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom(); }
  /// The rectangle grown by `d` on every side (shrunk when d < 0).
  Rect grown(int d) const { return {x - d, y - d, width + 2 * d, height + 2 * d}; }
};

enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

/// A `width` x `height` rectangle in `corner` of `frame`, `margin` from its edges. unit: px
inline Rect corner_rect(const Rect& frame, Corner corner, int width, int height, int margin) {
  const bool right = corner == Corner::kTopRight || corner == Corner::kBottomRight;
  const bool bottom = corner == Corner::kBottomLeft || corner == Corner::kBottomRight;
  return {right ? frame.right() - margin - width : frame.x + margin,
          bottom ? frame.bottom() - margin - height : frame.y + margin, width, height};
}

/// The shared look.
struct Style {
  Rgb ink{245, 245, 240};     ///< Text and leader lines.
  Rgb halo{12, 12, 16};       ///< Around glyphs and lines.
  Rgb panel{16, 18, 24};      ///< Behind legends and insets.
  double panel_alpha = 0.72;  ///< unit: 1
  double halo_alpha = 0.85;   ///< unit: 1
};

/// Sizes in the scene are pixels of a 720-line frame; other frame heights scale them, so a
/// layout keeps its proportions at any resolution (the goldens render at 240 lines).
inline int scaled_px(int px_at_720, int frame_height) {
  return std::max(1, static_cast<int>(px_at_720 * static_cast<double>(frame_height) / 720.0 + 0.5));
}

}  // namespace systole::overlay
