// The contact keys (docs/contact.md): contact pairs, colliders and tethers are read with
// their units and defaults, and every mistake names the file, line and key.

#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

constexpr const char* kTwoOrgans =
    "organs:\n"
    "  - name: heart\n"
    "    mesh: {procedural: heart}\n"
    "    regions:\n"
    "      - {name: aorta, tether: {stiffness: 40 N/m, offset: [0, -5 mm, 0]}}\n"
    "  - name: ribs\n"
    "    mesh: {procedural: chest_wall, detail: 1}\n"
    "    collider: true\n";

TEST(ContactSchema, PairsThicknessFrictionCollidersAndTethersAreRead) {
  const Scene s = load_from_string(std::string(kTwoOrgans) +
                                       "contact:\n  thickness: 3 mm\n  friction: 0.2\n  iterations: 6\n  substeps: 2\n"
                                       "  pairs:\n    - {organs: [heart, ribs], thickness: 1 mm}\n",
                                   "scenes/test.yaml");
  ASSERT_TRUE(s.contact.enabled);
  EXPECT_DOUBLE_EQ(s.contact.thickness_m, 0.003);
  EXPECT_DOUBLE_EQ(s.contact.friction, 0.2);
  EXPECT_EQ(s.contact.iterations, 6);
  EXPECT_EQ(s.contact.substeps, 2);
  ASSERT_EQ(s.contact.pairs.size(), 1u);
  EXPECT_TRUE(s.contact.pairs[0].has_thickness);
  EXPECT_DOUBLE_EQ(s.contact.pairs[0].thickness_m, 0.001);
  EXPECT_FALSE(s.contact.pairs[0].has_friction);
  EXPECT_TRUE(s.organs[1].collider);
  const Region& aorta = s.organs[0].regions[0];
  ASSERT_TRUE(aorta.tether.enabled);
  EXPECT_DOUBLE_EQ(aorta.tether.stiffness_N_per_m, 40);
  EXPECT_DOUBLE_EQ(aorta.tether.offset_m.y(), -0.005);
}

TEST(ContactSchema, WithoutAContactMapOrgansDoNotTouch) {
  const Scene s = load_from_string(testing::kMinimalOrgans, "scenes/test.yaml");
  EXPECT_FALSE(s.contact.enabled);
  EXPECT_FALSE(s.organs[0].collider);
}

TEST(ContactSchema, MistakesNameTheFileLineAndKey) {
  const std::string base = kTwoOrgans;
  struct Case {
    std::string yaml, expected;
  };
  const std::vector<Case> cases = {
      {base + "contact: {thikness: 2 mm}\n", "scenes/test.yaml:9:11: contact: unknown key 'thikness'"},
      {base + "contact: {pairs: [{organs: [heart, liver]}]}\n", "scenes/test.yaml:9:"},
      {base + "contact: {pairs: [{organs: [heart, liver]}]}\n", "no organ is named 'liver'"},
      {base + "contact: {pairs: [{organs: [heart, heart]}]}\n", "name two organs"},
      {base + "contact: {pairs: [{organs: [heart]}]}\n", "contact.pairs[0].organs"},
      {base + "contact: {pairs: [{organs: [heart, ribs]}, {organs: [ribs, heart]}]}\n", "listed twice"},
      {base + "contact: {thickness: 2}\n", "contact.thickness"},
      {base + "contact: {friction: -1}\n", "contact.friction"},
      {"organs:\n  - name: heart\n    mesh: {procedural: heart}\n    regions:\n"
       "      - {name: aorta, pinned: true, tether: {stiffness: 40 N/m}}\n",
       "pinned or tether, not both"},
      {"organs:\n  - name: heart\n    mesh: {procedural: heart}\n    regions:\n"
       "      - {name: aorta, tether: {offset: [0, 0, 0]}}\n",
       "stiffness"},
  };
  for (const Case& c : cases) {
    const testing::Failure f = load_error(c.yaml);
    EXPECT_EQ(f.code, ExitCode::kDataError) << c.yaml;
    EXPECT_NE(f.message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << f.message;
  }
}

}  // namespace
}  // namespace systole::scene
