// systole bench: against a converged reference, error falls as the step shrinks and as
// the model's resolution rises; the Pareto front keeps only undominated runs.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "study/accuracy.h"

namespace systole::study {
namespace {

/// A coarse procedural heart (710 vertices) with beating ventricles and a pinned aorta.
scene::Scene small_heart() {
  scene::Scene s;
  s.path = "small_heart";
  s.name = "small_heart";
  scene::Organ heart;
  heart.name = "heart";
  heart.mesh.procedural = "heart";
  heart.mesh.detail = 1;
  heart.body.mass_kg = 0.3;
  heart.body.stiffness_N_per_m = 400;
  heart.body.volume_stiffness_Pa = 3000;
  heart.body.drag_per_s = 2;
  for (const char* name : {"left_ventricle", "right_ventricle"}) {
    scene::Region r;
    r.name = name;
    r.drive.waveform = scene::Waveform::kCardiac;
    r.drive.rate_hz = 1.2;
    r.drive.amplitude = 0.14;
    r.drive.systolic_fraction = 0.36;
    heart.regions.push_back(r);
  }
  scene::Region aorta;
  aorta.name = "aorta";
  aorta.pinned = true;
  heart.regions.push_back(aorta);
  s.organs.push_back(heart);
  return s;
}

TEST(Bench, ErrorFallsWithTheStepAndWithResolution) {
  BenchOptions options;
  options.reference_dt_s = 1.0 / 480;
  options.reference_substeps = 16;
  using M = scene::SolverMethod;
  options.grid = {{M::kXpbd, 1.0 / 480, 2, 0}, {M::kXpbd, 1.0 / 480, 8, 0},  // step
                  {M::kXpbd, 1.0 / 240, 4, 3}, {M::kXpbd, 1.0 / 240, 4, 12}, {M::kXpbd, 1.0 / 240, 4, 0}};  // resolution
  const BenchReport report = run_bench(small_heart(), options);
  ASSERT_EQ(report.results.size(), 5u);
  EXPECT_DOUBLE_EQ(report.options.duration_s, 2.5);  // Three whole beats at 72 bpm.
  for (const auto& r : report.results) {
    ASSERT_TRUE(r.diverged.empty()) << r.config.label();
    EXPECT_GT(r.rms_error_pct, 0) << r.config.label();
    EXPECT_GE(r.max_error_pct, r.rms_error_pct) << r.config.label();
  }
  const auto& res = report.results;
  EXPECT_GT(res[0].rms_error_pct, res[1].rms_error_pct);  // Smaller substeps, smaller error.
  EXPECT_GT(res[2].rms_error_pct, res[3].rms_error_pct);  // Finer lattice, smaller error...
  EXPECT_GT(res[3].rms_error_pct, res[4].rms_error_pct);  // ...and the full model smaller still.
  EXPECT_LT(res[2].particles, res[3].particles);
  EXPECT_LT(res[3].particles, res[4].particles);
}

TEST(Bench, ParetoFrontKeepsOnlyUndominatedRuns) {
  std::vector<BenchResult> runs(4);
  runs[0].cost_ms_per_s = 10, runs[0].rms_error_pct = 3;
  runs[1].cost_ms_per_s = 100, runs[1].rms_error_pct = 1;
  runs[2].cost_ms_per_s = 120, runs[2].rms_error_pct = 2;  // Dominated by run 1.
  runs[3].cost_ms_per_s = 1, runs[3].rms_error_pct = 0.5;
  runs[3].diverged = "blew up";  // Never on the front.
  mark_pareto(runs);
  EXPECT_TRUE(runs[0].pareto);
  EXPECT_TRUE(runs[1].pareto);
  EXPECT_FALSE(runs[2].pareto);
  EXPECT_FALSE(runs[3].pareto);
}

TEST(Bench, GridCombinesTheListsOnce) {
  using M = scene::SolverMethod;
  const auto grid = grid_of({M::kXpbd, M::kExplicit}, {1.0 / 240, 1.0 / 120}, {2, 4}, {0, 8});
  // xpbd: 2 steps x 2 substeps x 2 models; explicit: its stable step only, x 2 models.
  EXPECT_EQ(grid.size(), 10u);
  EXPECT_EQ(grid.back().label(), "explicit auto lattice 8");
}

}  // namespace
}  // namespace systole::study
