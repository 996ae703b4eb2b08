// ctest-labels: no-sanitizers
// The material does not depend on the mesh: the shipped heart at mesh detail 3, 4 and 5
// (2,502 to 9,641 particles) beats alike - each driven region's peak-to-peak radial
// excursion within 5 % of the finest mesh's (docs/accuracy.md, "One material at any
// resolution"). Detail 3 is what the solid heart's scenes ship, its cheaper setting
// (tests/support/solid-heart.yaml: scenes/heart.yaml before it took the anatomical heart).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/load.h"
#include "sim/motion_error.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::test {
namespace {

/// Per driven region, the peak-to-peak of its vertices' mean distance from the organ's rest
/// centroid over the second beat (the first settles). unit: m
std::vector<double> region_excursions(int detail) {
  scene::Scene s = scene::load(source("tests/support/solid-heart.yaml"), {"organs.0.mesh.detail=" + std::to_string(detail)});
  s.output.fps = 60;
  s.output.duration_s = 2 * 60.0 / 72;
  world::World w = world::build_world(s);
  const world::OrganBody& heart = w.organs[0];
  const auto& rest = heart.geometry.mesh.surface.positions;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : rest) centre += p / double(rest.size());
  std::vector<std::vector<int>> members(heart.model.regions.size());
  for (std::size_t v = 0; v < heart.geometry.vertex_region.size(); ++v) {
    if (heart.geometry.vertex_region[v] >= 0) members[heart.geometry.vertex_region[v]].push_back(static_cast<int>(v));
  }
  std::vector<double> lo(members.size(), 1e9), hi(members.size(), -1e9);
  Eigen::Matrix3Xd x;
  const int frames = static_cast<int>(std::lround(s.output.duration_s * 60));
  for (int f = 1; f <= frames; ++f) {
    world::advance_to_frame(w, f);
    if (f <= frames / 2) continue;
    world::render_positions(heart, x);
    for (std::size_t r = 0; r < members.size(); ++r) {
      const double d = sim::mean_radial_distance_m(x, members[r], centre);
      lo[r] = std::min(lo[r], d);
      hi[r] = std::max(hi[r], d);
    }
  }
  std::vector<double> out;
  for (std::size_t r = 0; r < members.size(); ++r) {
    if (s.organs[0].regions[r].drive.waveform != scene::Waveform::kNone) out.push_back(hi[r] - lo[r]);
  }
  return out;
}

TEST(MeshIndependence, EveryDrivenRegionBeatsAlikeAtDetailThreeFourAndFive) {
  const std::vector<double> finest = region_excursions(5);
  ASSERT_EQ(finest.size(), 5u) << "the heart's five driven regions";
  for (double e : finest) ASSERT_GT(e, 1e-3) << "each region moves by millimetres";
  for (int detail : {3, 4}) {
    const std::vector<double> coarse = region_excursions(detail);
    ASSERT_EQ(coarse.size(), finest.size());
    for (std::size_t r = 0; r < finest.size(); ++r) {
      std::printf("detail %d, region %zu: %.3f mm against %.3f mm\n", detail, r, 1e3 * coarse[r], 1e3 * finest[r]);
      EXPECT_NEAR(coarse[r] / finest[r], 1.0, 0.05) << "detail " << detail << ", driven region " << r;
    }
  }
}

}  // namespace
}  // namespace systole::test
