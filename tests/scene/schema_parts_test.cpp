// Pieces of the scene schema's tables (scene/schema/parts.h) read alone: path keys in time
// order, and the lights a scene gets when it names none.

#include "scene/schema/parts.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "scene/tree.h"

namespace systole::scene::schema {
namespace {

std::vector<PathKey> keys(const std::string& yaml) {
  const Node root = parse_yaml("motion: " + yaml + "\n", "s.yaml");
  std::vector<PathKey> out;
  path_keys("where").read(*root.find("motion"), out, "motion", Context{});
  return out;
}

std::string refusal(const std::string& yaml) {
  try {
    keys(yaml);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    return e.what();
  }
  return "";
}

TEST(SchemaParts, PathKeysReadTimesAndPositionsInTheirUnits) {
  const auto k = keys("[{time: 0 s, position: [0, 0, 0]}, {time: 500 ms, position: [1 cm, 0, -2 mm]}]");
  ASSERT_EQ(k.size(), 2u);
  EXPECT_EQ(k[0].time_s, 0.0);
  EXPECT_DOUBLE_EQ(k[1].time_s, 0.5);
  EXPECT_TRUE(k[1].position_m.isApprox(Eigen::Vector3d(0.01, 0, -0.002)));
}

TEST(SchemaParts, PathKeysMustGoForwardInTime) {
  const std::string message = refusal("[{time: 1 s, position: [0, 0, 0]}, {time: 1 s, position: [1, 0, 0]}]");
  EXPECT_NE(message.find("times must increase"), std::string::npos) << message;
  EXPECT_NE(refusal("[{time: 2 s, position: [0, 0, 0]}, {time: 1 s, position: [1, 0, 0]}]"), "");
}

TEST(SchemaParts, PathKeysNeedATimeAndAPositionAndAtLeastOneKey) {
  EXPECT_NE(refusal("[{time: 1 s}]"), "");
  EXPECT_NE(refusal("[{position: [0, 0, 0]}]"), "");
  EXPECT_NE(refusal("[]"), "");
  EXPECT_NE(refusal("[{time: 1 s, position: [0, 0, 0], speed: 3}]"), "");  // Unknown key.
}

TEST(SchemaParts, DefaultLightsAreAWarmKeyAndACoolerDimmerFill) {
  const std::vector<Light> lights = default_lights();
  ASSERT_EQ(lights.size(), 2u);
  const Light &key = lights[0], &fill = lights[1];
  EXPECT_GT(key.intensity, fill.intensity);
  EXPECT_GE(key.color.x(), key.color.z());   // Warm: red over blue.
  EXPECT_GE(fill.color.z(), fill.color.x());  // Cool: blue over red.
  for (const Light& l : lights) EXPECT_GT(l.direction.norm(), 0.0);
  // From opposite sides.
  EXPECT_LT(key.direction.x() * fill.direction.x(), 0.0);
}

}  // namespace
}  // namespace systole::scene::schema
