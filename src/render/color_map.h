#pragma once
// Colour maps for teaching: what a surface colour means, as data an overlay can draw a
// colour bar or a legend from. No OpenGL here: the app maps values to per-vertex sRGB
// colours on the CPU (render::Renderer::update_colors) - a few thousand vertices a frame.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace systole::render {

enum class ColorMapKind {
  kDiverging,   ///< Moreland's cool-warm: blue (low) - light grey (middle) - red (high).
  kSequential,  ///< Inferno-like: dark purple (low) - red - yellow (high).
};

/// A colour bar: values in [lo, hi] mapped to sRGB, clamped outside.
struct ColorMap {
  ColorMapKind kind = ColorMapKind::kDiverging;
  double lo = -0.15;        ///< Value at the low end. unit: as `quantity`
  double hi = 0.15;         ///< Value at the high end. unit: as `quantity`
  std::string quantity;     ///< What is shown, for the bar's caption: "strain (L - L0) / L0".
  std::string low_label;    ///< Meaning of the low end: "shortened".
  std::string high_label;   ///< Meaning of the high end: "stretched".

  /// sRGB colour of `value` (piecewise linear between five stops, in sRGB).
  scene::Color at(double value) const;
};

/// The colour map an organ's `color_by` uses (strain: diverging, activation: sequential),
/// with the organ's `color_range`; `has` is false for material and region (no colour bar).
struct OrganColorMap {
  bool has = false;
  ColorMap map;
};
OrganColorMap organ_color_map(const scene::Organ& organ);

/// A region's name and the colour it is drawn in, for a legend.
struct RegionSwatch {
  std::string name;
  scene::Color color;  ///< sRGB
};

/// The colour of region `index` under color_by `region`: its own `color`, else entry
/// index % 8 of a fixed palette (Okabe & Ito's colour-blind-safe set, black left out).
scene::Color region_palette_color(const scene::Organ& organ, int index);

/// The regions as color_by draws them (material: only regions with a colour; region:
/// every region). Empty for strain and activation.
std::vector<RegionSwatch> region_legend(const scene::Organ& organ);

/// Static per-vertex colours for color_by material and region (sRGB); strain and
/// activation start at the map's colour of 0 and change every frame.
std::vector<scene::Color> static_vertex_colors(const scene::Organ& organ, const std::vector<int>& vertex_region);

}  // namespace systole::render
