#include "study/driven_regions.h"

#include <algorithm>

#include "sim/motion_error.h"

namespace systole::study {

std::vector<DrivenRegion> driven_regions(const scene::Scene& scene, const world::World& world) {
  std::vector<DrivenRegion> out;
  int offset = 0;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& geometry = world.organs[o].geometry;
    const auto& rest = geometry.mesh.surface.positions;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : rest) centre += p / double(std::max<std::size_t>(1, rest.size()));
    const auto& regions = scene.organs[o].regions;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const scene::Drive& d = regions[r].drive;
      const bool periodic = d.waveform != scene::Waveform::kNone && d.rate_hz > 0 && d.irregularity == 0 &&
                            (d.rate_end_hz == 0 || d.rate_end_hz == d.rate_hz);
      if (!periodic) continue;
      DrivenRegion region{scene.organs[o].name + "." + regions[r].name, {}, centre, d.rate_hz};
      for (std::size_t v = 0; v < geometry.vertex_region.size(); ++v) {
        if (geometry.vertex_region[v] == static_cast<int>(r)) region.vertices.push_back(offset + static_cast<int>(v));
      }
      if (!region.vertices.empty()) out.push_back(std::move(region));
    }
    const scene::Drive& v = scene.organs[o].body.volume_drive;
    if (v.waveform != scene::Waveform::kNone && v.rate_hz > 0 && v.irregularity == 0 &&
        (v.rate_end_hz == 0 || v.rate_end_hz == v.rate_hz)) {
      // A volume drive beats the whole organ: its region is every vertex.
      DrivenRegion whole{scene.organs[o].name + ".volume_drive", {}, centre, v.rate_hz};
      for (std::size_t k = 0; k < rest.size(); ++k) whole.vertices.push_back(offset + static_cast<int>(k));
      out.push_back(std::move(whole));
    }
    offset += static_cast<int>(rest.size());
  }
  return out;
}

double radial_excursion_m(const DrivenRegion& region, const Eigen::Matrix3Xd& stacked_positions) {
  return sim::mean_radial_distance_m(stacked_positions, region.vertices, region.centre);
}

}  // namespace systole::study
