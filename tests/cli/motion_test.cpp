// ctest-labels: slow-under-sanitizers
// `systole motion` on the shipped heart (beats that repeat once it has rung out of its rest
// shape, linings inside its walls: exit 0, and no lining in an outside view), on the same
// heart struck once mid-run (a beat that differs: exit 1, naming the region and the beat),
// and on the shipped multi-part heart: its parts stay apart in the lattice it gets, and pass
// through each other on the full model.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/run.h"

namespace systole::test {
namespace {

TEST(Motion, TheShippedHeartRepeatsItsBeat) {
  // The anatomical heart's ventricles are damped lightly (1 ms, so they twist), and the
  // blood's phases carry each beat's filling into the next: the right ventricle's third beat
  // is still 2.3 % off its second, the fourth within 0.3 % of the third. Beats 4 to 6 are
  // compared.
  const auto r = run(systole() + " motion " + source("scenes/heart.yaml") + " --duration 5.2 --settle 3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("heart.right_ventricle"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("first 3 left out"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("periodic (every beat within 2 % of the one before): yes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("parts of heart: a generated anatomy"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("linings of heart (1844 vertices) against its walls' outside, 156 frames: none outside"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("linings inside their walls: yes"), std::string::npos) << r.output;
}

TEST(Motion, AnOutsideViewOfTheShippedHeartShowsNoLining) {
  const auto r = run(systole() + " motion " + source("scenes/heart.yaml") +
                     " --duration 0.5 --outside-view -D output.width=320 -D output.height=180");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("outside view (uncut, opaque, coloured by region, 320x180), 15 frames: no lining pixel"),
            std::string::npos) << r.output;
}

TEST(Motion, ABeatDisturbedByAPushIsNotPeriodic) {
  const auto dir = scratch("motion-push");
  std::ifstream in(source("scenes/heart.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  // The mesh is generated, so the copy needs nothing beside it.
  scene += "interactions:\n"
           "  - poke: {organ: heart, at: [0.02, -0.03, 0.03], radius: 3 cm, force: [-1.5, 0, -3], start: 1.9 s, "
           "duration: 0.15 s}\n";
  std::ofstream(dir / "pushed.yaml") << scene;
  const auto r = run(systole() + " motion " + (dir / "pushed.yaml").string() + " --duration 4");
  ASSERT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("NOT PERIODIC"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(beat 2)"), std::string::npos) << r.output;  // 1.9 s is in beat 2 (1.67-2.5 s).
  EXPECT_NE(r.output.find("periodic (every beat within 2 % of the one before): no"), std::string::npos) << r.output;
}

TEST(Motion, TheAtlasHeartsPartsAreCheckedAndKeptApart) {
  const auto r = run(systole() + " motion " + source("scenes/atlas-heart.yaml") + " --duration 2.6");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("body heart: lattice"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("left_ventricle, right_ventricle"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("parts kept apart (no crossing beyond 0.1 mm): yes"), std::string::npos) << r.output;
}

TEST(Motion, TheAtlasHeartsPartsPassThroughEachOtherWithoutTheLattice) {
  // Every vertex a particle: the overlapping chambers move each on its own, and the right
  // ventricle's wall, lying against the left's, is pushed through it.
  const auto r = run(systole() + " motion " + source("scenes/atlas-heart.yaml") +
                     " --duration 1.8 -D organs.0.body.lattice=0");
  ASSERT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("PARTS PASS THROUGH"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("parts kept apart (no crossing beyond 0.1 mm): no"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace systole::test
