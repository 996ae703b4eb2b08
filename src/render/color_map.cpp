#include "render/color_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace systole::render {
namespace {

using Stops = std::array<scene::Color, 5>;

scene::Color rgb8(int r, int g, int b) { return scene::Color(r / 255.0, g / 255.0, b / 255.0); }

// K. Moreland, "Diverging Color Maps for Scientific Visualization" (2009), cool-warm,
// sampled at 0, 1/4, 1/2, 3/4, 1.
const Stops kCoolWarm = {rgb8(59, 76, 192), rgb8(141, 176, 254), rgb8(221, 221, 221), rgb8(244, 154, 123),
                         rgb8(180, 4, 38)};
// After matplotlib's "inferno" (van der Walt & Smith), its darkest fifth left out so the
// low end stays visible on the dark background.
const Stops kInferno = {rgb8(66, 10, 104), rgb8(147, 38, 103), rgb8(221, 81, 58), rgb8(252, 165, 10),
                        rgb8(252, 255, 164)};

// M. Okabe and K. Ito, "Color Universal Design" (2002), without black.
const std::array<scene::Color, 7> kPalette = {rgb8(230, 159, 0), rgb8(86, 180, 233), rgb8(0, 158, 115),
                                              rgb8(240, 228, 66), rgb8(0, 114, 178), rgb8(213, 94, 0),
                                              rgb8(204, 121, 167)};

}  // namespace

scene::Color ColorMap::at(double value) const {
  const Stops& stops = kind == ColorMapKind::kDiverging ? kCoolWarm : kInferno;
  double u = (value - lo) / (hi - lo);
  if (!std::isfinite(u)) u = 0.5;
  u = std::clamp(u, 0.0, 1.0) * 4;
  const int i = std::min(static_cast<int>(u), 3);
  const double f = u - i;
  return stops[i] * (1 - f) + stops[i + 1] * f;
}

OrganColorMap organ_color_map(const scene::Organ& organ) {
  OrganColorMap out;
  if (organ.color_by == scene::ColorBy::kStrain) {
    out.has = true;
    out.map = {ColorMapKind::kDiverging, organ.color_range[0], organ.color_range[1], "strain (L - L0) / L0",
               "shortened", "stretched"};
  } else if (organ.color_by == scene::ColorBy::kActivation) {
    out.has = true;
    out.map = {ColorMapKind::kSequential, organ.color_range[0], organ.color_range[1], "activation phi(t)", "relaxed",
               "contracted"};
  }
  return out;
}

scene::Color region_palette_color(const scene::Organ& organ, int index) {
  const scene::Region& region = organ.regions[static_cast<std::size_t>(index)];
  if (region.has_color) return region.color;
  return kPalette[static_cast<std::size_t>(index) % kPalette.size()];
}

std::vector<RegionSwatch> region_legend(const scene::Organ& organ) {
  std::vector<RegionSwatch> legend;
  for (std::size_t r = 0; r < organ.regions.size(); ++r) {
    if (organ.color_by == scene::ColorBy::kRegion) {
      legend.push_back({organ.regions[r].name, region_palette_color(organ, static_cast<int>(r))});
    } else if (organ.color_by == scene::ColorBy::kMaterial && organ.regions[r].has_color) {
      legend.push_back({organ.regions[r].name, organ.regions[r].color});
    }
  }
  return legend;
}

std::vector<scene::Color> static_vertex_colors(const scene::Organ& organ, const std::vector<int>& vertex_region) {
  const OrganColorMap map = organ_color_map(organ);
  std::vector<scene::Color> colors(vertex_region.size(), map.has ? map.map.at(0) : organ.material.color);
  if (map.has) return colors;
  for (std::size_t i = 0; i < vertex_region.size(); ++i) {
    const int r = vertex_region[i];
    if (r < 0) continue;
    if (organ.color_by == scene::ColorBy::kRegion) colors[i] = region_palette_color(organ, r);
    else if (organ.regions[static_cast<std::size_t>(r)].has_color) colors[i] = organ.regions[static_cast<std::size_t>(r)].color;
  }
  return colors;
}

}  // namespace systole::render
