// Spring colouring: no two springs of one colour share a particle, so a colour can be
// solved in any order or in parallel; greedy in index order, so the same input always
// gives the same colours.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "sim/graph_coloring.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

TEST(GraphColoring, NoTwoPairsOfOneColourShareAParticleOnABallsSprings) {
  const test::BeatingBall ball(3);
  const Model m = ball.model();
  std::vector<int> a, b;
  for (int j = 0; j < m.springs.size(); ++j) a.push_back(m.springs.a[j]), b.push_back(m.springs.b[j]);
  const std::vector<int> color = color_pairs(a, b, m.particle_count());
  ASSERT_EQ(color.size(), a.size());
  std::set<std::pair<int, int>> used;  // (colour, particle)
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_TRUE(used.insert({color[j], a[j]}).second) << "spring " << j;
    EXPECT_TRUE(used.insert({color[j], b[j]}).second) << "spring " << j;
  }
  // An icosphere's vertices have 5 or 6 neighbours: greedy colouring needs few colours.
  EXPECT_LE(*std::max_element(color.begin(), color.end()) + 1, 12);
  EXPECT_EQ(color_pairs(a, b, m.particle_count()), color) << "deterministic";
}

TEST(GraphColoring, APathAlternatesTwoColours) {
  const std::vector<int> a = {0, 1, 2, 3}, b = {1, 2, 3, 4};
  EXPECT_EQ(color_pairs(a, b, 5), (std::vector<int>{0, 1, 0, 1}));
}

}  // namespace
}  // namespace systole::sim
