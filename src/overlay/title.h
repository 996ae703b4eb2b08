#pragma once
// A title across the top of a frame or of one view of a split screen.

#include <string>

#include "common/image.h"
#include "overlay/layout.h"

namespace systole::overlay {

/// Draws `text` centred at the top of `rect` over a halo. `size_px` 0: rect.height / 24,
/// at least 10 px. Returns the text's box. unit: px
Rect draw_title(Image& image, const Rect& rect, const std::string& text, plot::Font& font, int size_px = 0,
                const Style& style = {});
/// The same with a font of its own (loads the font: keep a Font for every frame of a clip).
Rect draw_title(Image& image, const Rect& rect, const std::string& text, int size_px = 0);

}  // namespace systole::overlay
