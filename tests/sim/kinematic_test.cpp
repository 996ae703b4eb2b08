// A kinematic region moves along its prescribed path and carries the body with it.

#include <gtest/gtest.h>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/shapes.h"

namespace systole::sim {
namespace {

using sim::Method;

class Kinematic : public ::testing::TestWithParam<Method> {};

TEST_P(Kinematic, RegionFollowsItsPathAndCarriesTheBody) {
  const auto surface = test::icosphere(0.05, 2);
  std::vector<int> region(surface.positions.size());
  for (std::size_t i = 0; i < region.size(); ++i) region[i] = surface.positions[i].y() < -0.04 ? 0 : -1;
  sim::OrganParams organ;
  organ.name = "ball";
  organ.body.mass_kg = 1.0;  // Heavy and soft, so the explicit solver runs at 1 ms substeps.
  organ.body.stiffness_N_per_m = 50;
  organ.body.damping_s = 0.002;
  organ.body.drag_per_s = 5;
  sim::RegionParams base;  // The base is lowered by 2 cm over one second, then held.
  base.name = "base";
  base.pinned = true;
  base.motion = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0, -0.02, 0)}};
  organ.regions.push_back(base);
  ModelOptions options;
  options.solver.method = GetParam();
  options.solver.substeps = GetParam() == Method::kExplicit ? 8 : GetParam() == Method::kXpbd ? 4 : 1;
  options.clip_s = 10;
  const Model m = build_model(organ, test::geometry_of(surface, region), options);
  ASSERT_EQ(m.kinematic.size(), 1u);
  State s = initial_state(m);
  for (int i = 0; i < 3 * 120; ++i) {
    step(m, s, 1.0 / 120);
    ASSERT_FALSE(diagnose(m, s).has_value());
  }
  for (int i : m.kinematic[0].particles) {
    EXPECT_NEAR((s.x.col(i) - m.rest_positions.col(i)).y(), -0.02, 1e-12) << method_name(GetParam());
  }
  const double centroid_drop = m.rest_positions.row(1).mean() - s.x.row(1).mean();
  EXPECT_NEAR(centroid_drop, 0.02, 0.004) << "the free body followed its base down";
}

INSTANTIATE_TEST_SUITE_P(Solvers, Kinematic,
                         ::testing::Values(Method::kXpbd, Method::kExplicit, Method::kImplicit, Method::kProjective),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace systole::sim
