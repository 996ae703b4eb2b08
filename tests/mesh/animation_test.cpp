// Animated mesh files: morph-target and skinned glTF animations sampled into poses.

#include "mesh/animation.h"

#include <gtest/gtest.h>

#include <cstring>

#include "common/error.h"
#include "mesh/gltf_writer.h"
#include "mesh/icosphere.h"
#include "mesh/import.h"
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
  const auto file = scratch("morph.gltf");
  write_gltf(file, icosphere(0.03, 2), Motion::kMorph);
  const std::vector<Eigen::Vector3d> rest = import_mesh(file).surface.positions;
  const AnimationPoses a = import_animation(file, rest, 4);
  ASSERT_EQ(a.poses.size(), 4u);
  EXPECT_DOUBLE_EQ(a.duration_s, 1.0);
  EXPECT_EQ(a.phases, (std::vector<double>{0, 0.25, 0.5, 0.75}));
  // Weight 0 at 0 s, 0.5 at 0.25 s, 1 at 0.5 s: the ball grows by 0, 10 and 20 %.
  for (const auto& [k, grow] : {std::pair{0, 0.0}, {1, 0.1}, {2, 0.2}, {3, 0.1}}) {
    std::vector<Eigen::Vector3d> expected;
    for (const auto& p : rest) expected.push_back((1 + grow) * p);
    EXPECT_LT(max_error(a.poses[k], expected), 1e-6) << "pose " << k;
  }
}

TEST(Animation, SkinnedVerticesFollowTheirAnimatedJoint) {
  const auto file = scratch("skin.gltf");
  write_gltf(file, icosphere(0.03, 1), Motion::kSkin);
  const std::vector<Eigen::Vector3d> rest = import_mesh(file).surface.positions;
  const AnimationPoses a = import_animation(file, rest, 4);
  ASSERT_EQ(a.poses.size(), 4u);
  for (const auto& [k, lift] : {std::pair{0, 0.0}, {1, 0.005}, {2, 0.01}, {3, 0.005}}) {
    std::vector<Eigen::Vector3d> expected;
    for (const auto& p : rest) expected.push_back(p + Eigen::Vector3d(0, lift, 0));
    EXPECT_LT(max_error(a.poses[k], expected), 1e-6) << "pose " << k;
  }
}

TEST(Animation, PosesFollowTheOrganVerticesOrderAndRefuseAnotherMesh) {
  const auto file = scratch("morph-order.gltf");
  write_gltf(file, icosphere(0.03, 1), Motion::kMorph);
  std::vector<Eigen::Vector3d> rest = import_mesh(file).surface.positions;
  std::reverse(rest.begin(), rest.end());
  const AnimationPoses a = import_animation(file, rest, 2);
  for (std::size_t i = 0; i < rest.size(); ++i) EXPECT_LT((a.poses[1][i] - 1.2 * rest[i]).norm(), 1e-6);

  rest[3] += Eigen::Vector3d(0.01, 0, 0);  // Not a vertex of the file.
  try {
    import_animation(file, rest, 2);
    FAIL() << "a vertex with no counterpart was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("morph-order.gltf: the organ's vertex 3 has no counterpart"), std::string::npos) << e.what();
  }
}

TEST(Animation, AFileWithoutAnimationIsRefused) {
  const auto file = scratch("still.obj");
  write_text(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  try {
    import_animation(file, import_mesh(file).surface.positions, 4);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("holds no animation"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace systole::mesh
