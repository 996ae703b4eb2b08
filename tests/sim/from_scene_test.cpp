// The one bridge from the scene to the simulator: every value arrives, in the same units,
// and messages keep pointing into the scene file.

#include <gtest/gtest.h>

#include "scene/load.h"
#include "sim/from_scene.h"

namespace systole::sim {
namespace {

TEST(FromScene, TranslatesOrganRegionsDrivesSolverAndInteractions) {
  const scene::Scene s = scene::load_from_string(
      "seed: 5\n"
      "organs:\n"
      "  - name: ball\n"
      "    mesh: {procedural: heart, detail: 1}\n"
      "    body: {mass: 200 g, stiffness: 300 N/m, damping: 5 ms, lattice: 6}\n"
      "    regions:\n"
      "      - {name: left_ventricle, stiffness: 2, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1,"
      " delay: 160 ms, systolic_fraction: 0.3}}\n"
      "      - {name: aorta, pinned: true}\n"
      "interactions:\n"
      "  - {poke: {organ: ball, at: [0, 0, 0.03], radius: 1 cm, force: [0, 0, -1], start: 1 s, duration: 0.2 s}}\n"
      "solver: {method: implicit, dt: 1/120 s, substeps: 2, threads: 2}\n"
      "output: {fps: 30, duration: 2 s}\n",
      "mine.yaml");
  const OrganParams organ = organ_params(s.organs[0]);
  EXPECT_EQ(organ.name, "ball");
  EXPECT_EQ(organ.where.rfind("mine.yaml:", 0), 0u) << organ.where;
  EXPECT_DOUBLE_EQ(organ.body.mass_kg, 0.2);
  EXPECT_DOUBLE_EQ(organ.body.damping_s, 0.005);
  EXPECT_EQ(organ.body.lattice, 6);
  ASSERT_EQ(organ.regions.size(), 2u);
  const RegionParams& lv = organ.regions[0];
  EXPECT_EQ(lv.drive.waveform, Waveform::kCardiac);
  EXPECT_DOUBLE_EQ(lv.drive.rate_hz, 1.2);
  EXPECT_DOUBLE_EQ(lv.drive.delay_s, 0.16);
  EXPECT_DOUBLE_EQ(lv.drive.systolic_fraction, 0.3);
  EXPECT_DOUBLE_EQ(lv.stiffness_scale, 2);
  EXPECT_TRUE(organ.regions[1].pinned);

  const ModelOptions options = model_options(s, "ball", 1.0 / 120);
  EXPECT_EQ(options.solver.method, Method::kImplicit);
  EXPECT_EQ(options.solver.substeps, 2);
  EXPECT_EQ(options.solver.threads, 2);
  EXPECT_EQ(options.seed, 5u);
  EXPECT_DOUBLE_EQ(options.clip_s, 2.0);
  ASSERT_EQ(options.interactions.size(), 1u);
  EXPECT_EQ(options.interactions[0].kind, InteractionKind::kPoke);
  EXPECT_DOUBLE_EQ(options.interactions[0].radius_m, 0.01);
  EXPECT_EQ(options.interactions[0].where.rfind("mine.yaml:", 0), 0u);
  EXPECT_TRUE(model_options(s, "other", 1.0 / 120).interactions.empty()) << "only the organ's own";
}

}  // namespace
}  // namespace systole::sim
