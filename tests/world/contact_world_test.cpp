// ctest-labels: slow-under-sanitizers
// The chest as one system (scenes/chest.yaml, docs/contact.md): the organs step together,
// no vertex of one organ goes deeper into another than the contact thickness at any frame,
// the coupled step gives the same bits at 1 and 2 threads, and a collider never moves.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "common/error.h"
#include "scene/load.h"
#include "sim/contact/contact.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::world {
namespace {

/// The shipped chest, its rib cage at detail 1 so the brute-force inside test stays quick.
scene::Scene chest(std::vector<std::string> overrides = {}) {
  overrides.push_back("organs.rib_cage.mesh.detail=1");
  return scene::load(test::source("scenes/chest.yaml"), overrides);
}

TEST(ChestContact, NoVertexGoesDeeperThanTheThicknessAtAnyFrame) {
  const scene::Scene scene = chest();
  World w = build_world(scene);
  ASSERT_TRUE(w.coupling.enabled);
  ASSERT_GE(w.coupling.params.pairs.size(), 5u);
  double worst = 0;
  std::string where;
  for (int frame = 0; frame <= 15; ++frame) {  // Half a second: the heart's first beat, inspiration starting.
    advance_to_frame(w, frame);
    std::vector<sim::contact::Body> bodies = contact_bodies(w.organs);
    for (const sim::contact::PairParams& pair : w.coupling.params.pairs) {
      std::string which;
      const double depth = sim::contact::deepest_inside_m(bodies, pair, &which);
      EXPECT_LE(depth, pair.thickness_m) << "frame " << frame << ": " << which;
      if (depth > worst) worst = depth, where = which;
    }
  }
  EXPECT_GT(w.coupling.work.stats.contacts_total, 0) << "the organs touched";
  std::cout << "deepest vertex over 16 frames: " << worst * 1000 << " mm " << where << "\n";
}

TEST(ChestContact, TheColliderNeverMovesAndEveryOrganKeepsTheClock) {
  World w = build_world(chest({"output.duration=0.2 s"}));
  int ribs = -1;
  for (std::size_t i = 0; i < w.organs.size(); ++i)
    if (w.organs[i].collider) ribs = static_cast<int>(i);
  ASSERT_GE(ribs, 0);
  const Eigen::Matrix3Xd rest = w.organs[ribs].state.x;
  advance_to_frame(w, 6);
  EXPECT_EQ((w.organs[ribs].state.x - rest).cwiseAbs().maxCoeff(), 0.0);
  for (const OrganBody& o : w.organs) EXPECT_NEAR(o.state.time_s, 0.2, 1e-9) << o.model.name;
}

bool same_bits(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

TEST(ChestContact, OneAndTwoThreadsGiveTheSameFrames) {
  World one = build_world(chest({"solver.threads=1"})), two = build_world(chest({"solver.threads=2"}));
  advance_to_frame(one, 4);
  advance_to_frame(two, 4);
  ASSERT_GT(one.coupling.work.stats.contacts_total, 0);
  for (std::size_t i = 0; i < one.organs.size(); ++i) {
    EXPECT_TRUE(same_bits(one.organs[i].state.x, two.organs[i].state.x)) << one.organs[i].model.name;
    EXPECT_TRUE(same_bits(one.organs[i].state.v, two.organs[i].state.v)) << one.organs[i].model.name;
  }
}

TEST(ChestContact, AnOpenSurfaceInAPairIsRefusedByName) {
  // A 10 cm open sheet (two triangles' worth of grid) written as OBJ.
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / "contact_open";
  std::filesystem::create_directories(dir);
  const std::filesystem::path obj = dir / "sheet.obj";
  {
    std::ofstream out(obj);
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) out << "v " << 0.05 * i << " " << 0.05 * j << " 0\n";
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int a = j * 3 + i + 1;
        out << "f " << a << " " << a + 1 << " " << a + 4 << "\nf " << a << " " << a + 4 << " " << a + 3 << "\n";
      }
  }
  const std::string yaml = "organs:\n  - name: heart\n    mesh: {procedural: heart}\n  - name: sheet\n    mesh: {file: " +
                           obj.string() + ", units: m}\n    body: {lattice: 0}\ncontact: {}\n";
  try {
    build_world(scene::load_from_string(yaml, "scenes/test.yaml"));
    FAIL() << "an open surface in contact must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("'sheet' has an open or non-manifold surface"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace systole::world
