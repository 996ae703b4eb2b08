// Animated mesh files: morph-target and skinned glTF animations sampled into poses, each
// file's own surface (mesh/animated_surface.h).

#include "mesh/animation.h"
#include "mesh/gltf_read.h"

#include <gtest/gtest.h>

#include <cstring>

#include "common/error.h"
#include "mesh/gltf_writer.h"
#include "mesh/icosphere.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

using testing::scratch;
using testing::Motion;
using testing::write_gltf;
using testing::write_text;

double max_error(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double e = 0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, (a[i] - b[i]).norm());
  return e;
}

TEST(Animation, MorphTargetWeightsAreSampledOverTheAnimation) {
  // A glTF that animates weights only is read over nlohmann/json (mesh/gltf_read.h).
  const auto file = scratch("morph.gltf");
  write_gltf(file, icosphere(0.03, 2), Motion::kMorph);
  const auto a = read_gltf_morphs(file, 4, 1, 0);
  ASSERT_TRUE(a.has_value());
  ASSERT_EQ(a->poses.size(), 4u);
  EXPECT_DOUBLE_EQ(a->duration, 1.0);
  EXPECT_EQ(a->times, (std::vector<double>{0, 0.25, 0.5, 0.75}));
  // Weight 0 at 0 s, 0.5 at 0.25 s, 1 at 0.5 s: the ball grows by 0, 10 and 20 %.
  for (const auto& [k, grow] : {std::pair{0, 0.0}, {1, 0.1}, {2, 0.2}, {3, 0.1}}) {
    std::vector<Eigen::Vector3d> expected;
    for (const auto& p : a->rest) expected.push_back((1 + grow) * p);
    EXPECT_LT(max_error(a->poses[k], expected), 1e-6) << "pose " << k;
  }
  // The second of two cycles: its last half.
  const auto second = read_gltf_morphs(file, 2, 2, 1);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->times, (std::vector<double>{0.5, 0.75}));
}

TEST(Animation, SkinnedVerticesFollowTheirAnimatedJoint) {
  // Nodes move: not a weights-only glTF, so assimp reads it.
  const auto file = scratch("skin.gltf");
  write_gltf(file, icosphere(0.03, 1), Motion::kSkin);
  EXPECT_FALSE(read_gltf_morphs(file, 4, 1, 0).has_value());
  const AnimatedSurface a = read_animated_file(file, 4, 1, 0);
  ASSERT_EQ(a.poses.size(), 4u);
  EXPECT_FALSE(a.triangles.empty());
  for (const auto& [k, lift] : {std::pair{0, 0.0}, {1, 0.005}, {2, 0.01}, {3, 0.005}}) {
    std::vector<Eigen::Vector3d> expected;
    for (const auto& p : a.rest) expected.push_back(p + Eigen::Vector3d(0, lift, 0));
    EXPECT_LT(max_error(a.poses[k], expected), 1e-6) << "pose " << k;
  }
}

TEST(Animation, AFileWithoutAnimationIsRefused) {
  const auto file = scratch("still.obj");
  write_text(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  try {
    read_animated_file(file, 4, 1, 0);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("holds no animation"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace systole::mesh
