#pragma once
// Title cards and captions (docs/teaching-visuals.md): a card is full-frame text on the
// background colour shown before the clip; a caption is a line of text at the bottom of
// the clip over a time range. Both fade in and out. Text is set with plot::Font (FreeType,
// DejaVu Sans). Times are video time: the clip's frame f is shown at f / fps whatever its
// slow motion, because captions are read at the speed of the video.

#include <memory>
#include <vector>

#include "common/image.h"
#include "scene/scene.h"

namespace systole::plot {
class Font;
}

namespace systole::overlay {

/// Opacity of something shown over [from, to) with linear fades of `fade` at both ends, at
/// time `t`: 0 outside, 1 inside the fades. unit: 1 (times unit: s)
double fade_opacity(double t, double from_s, double to_s, double fade_s);

class CardPainter {
 public:
  /// Loads the font only when the scene has cards or captions (Error(kNoInput) when it is
  /// missing); a scene without them needs no font.
  explicit CardPainter(const scene::Scene& scene);
  ~CardPainter();
  CardPainter(const CardPainter&) = delete;
  CardPainter& operator=(const CardPainter&) = delete;

  /// Video frames of all title cards together: each lasts round(duration * fps).
  int card_frames() const { return card_frames_; }
  /// Title-card frame `k` (0 .. card_frames() - 1) at the output size.
  void draw_card(int k, Image& image);
  /// Draws the captions shown at clip frame `clip_frame` over `image` (none: unchanged).
  void draw_captions(int clip_frame, Image& image);

 private:
  const scene::Scene& scene_;
  std::unique_ptr<plot::Font> font_;
  std::vector<int> card_first_;  ///< First frame of each card.
  int card_frames_ = 0;
};

}  // namespace systole::overlay
