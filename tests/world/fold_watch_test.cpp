// The crumple watch: a driven region whose surface folds over itself for longer than a
// cycle stops the run; smooth motion of any size, a brief fold, or a fold in an undriven
// or pinned region does not.

#include "world/fold_watch.h"

#include <gtest/gtest.h>

#include <cmath>

namespace systole::world {
namespace {

// A flat n x n grid of 1 cm cells in the z = 0 plane, every vertex in region 0.
mesh::OrganGeometry flat_sheet(int n) {
  mesh::OrganGeometry g;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) g.mesh.surface.positions.emplace_back(0.01 * i, 0.01 * j, 0);
  }
  const auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      g.mesh.surface.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      g.mesh.surface.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  g.vertex_region.assign(g.mesh.surface.positions.size(), 0);
  return g;
}

scene::Organ organ_with(bool driven, bool pinned = false) {
  scene::Organ organ;
  organ.name = "sheet";
  scene::Region region;
  region.name = "wall";
  region.pinned = pinned;
  if (driven) {
    region.drive.waveform = scene::Waveform::kCardiac;
    region.drive.rate_hz = 1.0;
  }
  organ.regions.push_back(region);
  return organ;
}

Eigen::Matrix3Xd positions_of(const mesh::OrganGeometry& g, double fold_height, double scale = 1) {
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(g.mesh.surface.positions.size()));
  for (std::size_t v = 0; v < g.mesh.surface.positions.size(); ++v) {
    Eigen::Vector3d p = scale * g.mesh.surface.positions[v];
    // A zig-zag along x: every column of vertices alternately up and down, a crease at each.
    const int column = static_cast<int>(std::lround(g.mesh.surface.positions[v].x() / 0.01));
    p.z() += (column % 2 == 0 ? 0.0 : fold_height);
    x.col(static_cast<Eigen::Index>(v)) = p;
  }
  return x;
}

TEST(FoldWatch, ARegionFoldedForLongerThanACycleStopsTheRun) {
  const mesh::OrganGeometry g = flat_sheet(10);
  FoldWatch watch(organ_with(true), g);
  // Steep zig-zag (a 3 cm rise over 1 cm cells): most pairs turn by well over 60 degrees.
  const Eigen::Matrix3Xd crumpled = positions_of(g, 0.03);
  EXPECT_FALSE(watch.update(crumpled, 0.0)) << "the first folded frame starts the clock";
  ASSERT_EQ(watch.folded_shares().size(), 1u);
  EXPECT_GT(watch.folded_shares()[0], 0.25) << "every crease between strips (90 of the 280 pairs)";
  EXPECT_FALSE(watch.update(crumpled, 0.9)) << "within one cycle (1 s): a snap or a poke";
  const auto problem = watch.update(crumpled, 1.1);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("region 'wall' of 'sheet' is crumpling: "), std::string::npos) << *problem;
  EXPECT_NE(problem->find("for longer than a cycle of its drive (1.00 s)"), std::string::npos) << *problem;
}

TEST(FoldWatch, SmoothMotionOrABriefFoldPasses) {
  const mesh::OrganGeometry g = flat_sheet(10);
  FoldWatch watch(organ_with(true), g);
  // Shrunk to 60 % and gently rippled: a strong beat, no fold.
  for (int frame = 0; frame < 100; ++frame) {
    EXPECT_FALSE(watch.update(positions_of(g, 0.001, 0.6), frame / 30.0));
  }
  EXPECT_LT(watch.folded_shares()[0], 0.01);
  // Folded for half a cycle, then smooth again, then folded again: the clock restarts.
  EXPECT_FALSE(watch.update(positions_of(g, 0.03), 4.0));
  EXPECT_FALSE(watch.update(positions_of(g, 0.03), 4.5));
  EXPECT_FALSE(watch.update(positions_of(g, 0.0), 4.6));
  EXPECT_FALSE(watch.update(positions_of(g, 0.03), 5.0));
  EXPECT_FALSE(watch.update(positions_of(g, 0.03), 5.9));
}

TEST(FoldWatch, UndrivenAndPinnedRegionsAreNotWatched) {
  const mesh::OrganGeometry g = flat_sheet(6);
  FoldWatch pinned(organ_with(true, true), g);
  EXPECT_TRUE(pinned.folded_shares().empty());
  EXPECT_FALSE(pinned.update(positions_of(g, 0.03), 0));
  EXPECT_FALSE(pinned.update(positions_of(g, 0.03), 100));
  FoldWatch undriven(organ_with(false), g);
  EXPECT_TRUE(undriven.folded_shares().empty());
  EXPECT_FALSE(undriven.update(positions_of(g, 0.03), 100));
}

}  // namespace
}  // namespace systole::world
