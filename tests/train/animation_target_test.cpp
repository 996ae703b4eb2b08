// A target from an animated glTF (morph targets) of the organ's own mesh: its poses reach
// the training target placed like the organ (centring, unit, transform).

#include <gtest/gtest.h>

#include "common/error.h"
#include "mesh/gltf_writer.h"
#include "mesh/icosphere.h"
#include "mesh/organ.h"
#include "scene/load.h"
#include "train/target.h"
#include "train/train_test_util.h"

namespace systole::train {
namespace {

TEST(AnimationTarget, MorphAnimationPosesArePlacedLikeTheOrgan) {
  const auto dir = testing::scratch("animation_target");
  // A ball 3 units across in the file; the organ reads it in cm and doubles it.
  mesh::testing::write_gltf(dir / "ball.gltf", mesh::icosphere(1.5, 2), mesh::testing::Motion::kMorph);
  testing::write_text(dir / "ball.yaml",
                      "organs:\n"
                      "  - name: ball\n"
                      "    mesh: {file: ball.gltf, units: cm}\n"
                      "    transform: {scale: 2}\n"
                      "    regions: [{name: ball, drive: {waveform: sine, rate: 1 Hz, amplitude: 0.05}}]\n"
                      "    target: {rate: 2 Hz, animation: ball.gltf, samples: 8}\n"
                      "output: {width: 64, height: 48, fps: 30, duration: 1 s}\n");
  const scene::Scene scene = scene::load(dir / "ball.yaml");
  const mesh::OrganGeometry geometry = mesh::build_organ_geometry(scene.organs[0]);
  const TargetMotion target = load_target(scene.organs[0], geometry);
  ASSERT_EQ(target.particle_count(), static_cast<int>(geometry.mesh.surface.positions.size()));
  Eigen::Matrix3Xd at_rest, grown;
  target.positions(0.0, at_rest);
  target.positions(0.5, grown);  // Half the animation: the morph target's weight is 1.
  // The organ is centred, so its rest vertex p moves to p + 0.2 p (the morph) at half cycle.
  double worst = 0;
  for (Eigen::Index v = 0; v < grown.cols(); ++v) {
    const Eigen::Vector3d rest = geometry.mesh.surface.positions[static_cast<std::size_t>(v)];
    worst = std::max({worst, (at_rest.col(v) - rest).norm(), (grown.col(v) - 1.2 * rest).norm()});
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(geometry.mesh.surface.positions[0].norm(), 0.03, 1e-6) << "1.5 cm doubled";
}

TEST(AnimationTarget, SceneKeysAreChecked) {
  const auto dir = testing::scratch("animation_target_keys");
  const std::string head = "organs:\n  - name: ball\n    mesh: {procedural: heart, detail: 1}\n"
                           "    regions: [{name: apex, drive: {waveform: sine, rate: 1 Hz, amplitude: 0.05}}]\n";
  const std::string tail = "output: {width: 64, height: 48, fps: 30, duration: 1 s}\n";
  auto error_of = [&](const std::string& target) {
    testing::write_text(dir / "s.yaml", head + target + tail);
    try {
      scene::load(dir / "s.yaml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(error_of("    target: {rate: 1 Hz, animation: missing.glb}\n").find("s.yaml:5"), std::string::npos);
  EXPECT_NE(error_of("    target: {rate: 1 Hz, animation: missing.glb}\n").find("missing.glb is not found"), std::string::npos);
  EXPECT_NE(error_of("    target: {rate: 1 Hz, curves: [{region: apex, scale: [1, 0.9]}], samples: 8}\n").find("applies to an animation only"),
            std::string::npos);
  EXPECT_NE(error_of("    target: {rate: 1 Hz}\n").find("expected exactly one of frames, curves, animation"), std::string::npos);
  for (const std::string key : {"cycles: 2", "piece: 0", "units: mm", "align: {mode: affine}"}) {
    EXPECT_NE(error_of("    target: {rate: 1 Hz, curves: [{region: apex, scale: [1, 0.9]}], " + key + "}\n").find("applies to an animation only"),
              std::string::npos)
        << key;
  }
  EXPECT_NE(error_of("    target: {rate: 1 Hz, animation: missing.glb, align: {landmarks: [{target: [0, 0, 0], organ: [0, 0, 0]}]}}\n")
                .find("landmarks: expected 3..64 items; got 1"),
            std::string::npos);
  EXPECT_NE(error_of("    target: {rate: 1 Hz, animation: missing.glb, align: {mode: rigid}}\n").find("similarity"), std::string::npos);
}

TEST(AnimationTarget, AFileInOtherUnitsIsRefusedUntilTheTargetSaysThem) {
  const auto dir = testing::scratch("animation_target_units");
  // The ball's animation written in millimetres, the organ's mesh in metres.
  mesh::testing::write_gltf(dir / "ball.gltf", mesh::icosphere(0.015, 2), mesh::testing::Motion::kMorph);
  mesh::testing::write_gltf(dir / "ball_mm.gltf", mesh::icosphere(15, 2), mesh::testing::Motion::kMorph);
  const std::string head = "organs:\n  - name: ball\n    mesh: {file: ball.gltf}\n"
                           "    regions: [{name: ball, drive: {waveform: sine, rate: 1 Hz, amplitude: 0.05}}]\n";
  const std::string tail = "output: {width: 64, height: 48, fps: 30, duration: 1 s}\n";
  auto load = [&](const std::string& target) {
    testing::write_text(dir / "s.yaml", head + target + tail);
    const scene::Scene scene = scene::load(dir / "s.yaml");
    return load_target(scene.organs[0], mesh::build_organ_geometry(scene.organs[0]));
  };
  try {
    load("    target: {rate: 2 Hz, animation: ball_mm.gltf}\n");
    FAIL() << "a target 1000 times the organ was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("its file is in other units than the organ's mesh; give target.units"), std::string::npos)
        << e.what();
  }
  const TargetMotion target = load("    target: {rate: 2 Hz, animation: ball_mm.gltf, units: mm}\n");
  const TargetMotion same = load("    target: {rate: 2 Hz, animation: ball.gltf}\n");
  Eigen::Matrix3Xd a, b;
  target.positions(0.5, a);
  same.positions(0.5, b);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6) << "the file in mm moves the organ as the one in metres";
}

}  // namespace
}  // namespace systole::train
