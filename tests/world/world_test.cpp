#include "world/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/error.h"
#include "scene/load.h"
#include "support/run.h"

using namespace systole::test;  // support/run.h

namespace systole::world {
namespace {

scene::Scene heart() { return scene::load(test::source("scenes/heart.yaml"), {"output.duration=0.2 s"}); }

TEST(ChooseBody, AutoGivesAnOpenOrManyPieceOrHugeMeshFileALatticeAndEverythingElseTheFullModel) {
  scene::Organ organ;
  mesh::OrganGeometry g;
  g.report.triangles = 100, g.report.vertices = 60, g.report.components = 1;  // Closed, one piece.
  EXPECT_EQ(choose_body(organ, g).lattice, 0) << "a generated organ";
  organ.mesh.file = "organ.obj";
  EXPECT_EQ(choose_body(organ, g).lattice, 0) << "a closed surface in one piece";
  EXPECT_NE(choose_body(organ, g).reason.find("auto: full model"), std::string::npos);

  g.report.boundary_edges = 4;
  BodyChoice open = choose_body(organ, g);
  EXPECT_EQ(open.lattice, kAutoLattice);
  EXPECT_NE(open.reason.find("auto: lattice 12, since the surface is open:"), std::string::npos) << open.reason;
  g.report.boundary_edges = 0, g.report.components = 17, g.report.vertices = 81379;
  const BodyChoice atlas = choose_body(organ, g);
  EXPECT_EQ(atlas.lattice, kAutoLattice);
  EXPECT_NE(atlas.reason.find("since it is in 17 pieces and it has 81379 vertices"), std::string::npos) << atlas.reason;

  organ.body.lattice = 0;  // The scene decides when it says.
  EXPECT_EQ(choose_body(organ, g).lattice, 0);
  EXPECT_EQ(choose_body(organ, g).reason, "as the scene sets (body.lattice: 0)");
}

TEST(ChooseBody, ValidateSaysWhichBodyAndWhy) {
  const auto r = run(test::systole() + " validate " + test::source("scenes/own-mesh.yaml") + " -D organs.0.body.lattice=8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("  body: as the scene sets (body.lattice: 8)"), std::string::npos) << r.output;
  const auto a = run(test::systole() + " validate " + test::source("scenes/own-mesh.yaml"));
  EXPECT_NE(a.output.find("  body: auto: full model, every vertex a particle (a closed surface in one piece)"),
            std::string::npos)
      << a.output;
}

TEST(World, EveryOrganGetsABodyAndAWholeNumberOfStepsMakesAFrame) {
  const auto s = heart();
  const World w = build_world(s);
  ASSERT_EQ(w.organs.size(), s.organs.size());
  EXPECT_GE(w.steps_per_frame, 1);
  EXPECT_GT(w.dt_s, 0);
  // The step divides the frame period exactly (to rounding).
  EXPECT_NEAR(w.steps_per_frame * w.dt_s, w.frame_s, 1e-12 * w.frame_s);
  EXPECT_FALSE(w.step_reason.empty());
  for (const auto& body : w.organs) {
    Eigen::Matrix3Xd x;
    render_positions(body, x);
    EXPECT_EQ(x.cols(), static_cast<Eigen::Index>(body.geometry.mesh.surface.positions.size()));
    EXPECT_TRUE(x.allFinite());
  }
}

TEST(World, AdvancingMovesTheBodyAndFramesOnlyMoveForward) {
  World w = build_world(heart());
  Eigen::Matrix3Xd before, after, again;
  render_positions(w.organs[0], before);
  advance_to_frame(w, 3);
  render_positions(w.organs[0], after);
  EXPECT_EQ(w.frames_done, 3);
  EXPECT_GT((after - before).norm(), 0);  // The heart beats.
  advance_to_frame(w, 2);                 // Frames only move forward: nothing happens.
  render_positions(w.organs[0], again);
  EXPECT_EQ(w.frames_done, 3);
  EXPECT_EQ(after, again);
}

TEST(World, TheSameSceneBuildsTheSameBodiesBitForBit) {
  World a = build_world(heart()), b = build_world(heart());
  advance_to_frame(a, 2);
  advance_to_frame(b, 2);
  Eigen::Matrix3Xd xa, xb;
  render_positions(a.organs[0], xa);
  render_positions(b.organs[0], xb);
  EXPECT_EQ(xa, xb);
}

}  // namespace
}  // namespace systole::world
