#pragma once
// Region labels: a name placed beside its region on screen with a leader line to it,
// following the region as it moves, set over a halo so it reads on any background, and
// placed so labels do not overlap each other, the frame's edge or the insets.
//
// Placement is greedy, in the order given: each label tries positions along the direction
// from the organ's centre out through its anchor (the most natural place), then turned
// by growing angles, then further out; the first free one wins. It is decided afresh
// every frame (no memory of the last frame), so frame k is the same whatever else is
// rendered; a label may hop when another's box moves into its place.

#include <string>
#include <vector>

#include "common/image.h"
#include "overlay/layout.h"

namespace systole::overlay {

struct LabelRequest {
  std::string text;
  double anchor_x = 0, anchor_y = 0;  ///< Where the leader line ends: the region's projected centroid. unit: px
  double center_x = 0, center_y = 0;  ///< The organ's projected centre: the label goes outwards from it. unit: px
};

struct PlacedLabel {
  std::string text;
  double baseline_x = 0, baseline_y = 0;  ///< Where the text starts. unit: px
  Rect box;                               ///< The text's box, halo included. unit: px
  double leader_x0 = 0, leader_y0 = 0;    ///< Leader line start, on the box's edge. unit: px
  double anchor_x = 0, anchor_y = 0;      ///< Leader line end. unit: px
  bool free = true;                       ///< False: no free place was found; it overlaps the least.
};

/// Places the labels in `frame`, avoiding `keep_out` (insets, legends) and each other.
/// `font` must be set to the label size.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, const Rect& frame,
                                      const std::vector<Rect>& keep_out, plot::Font& font);

/// Draws placed labels: leader lines with a dot at the anchor, then the text, each over a halo.
void draw_labels(Image& image, const std::vector<PlacedLabel>& labels, plot::Font& font, const Style& style = {});

}  // namespace systole::overlay
