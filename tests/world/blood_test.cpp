// ctest-labels: slow-under-sanitizers
// The blood in the anatomical heart's ventricles (sim/circulation.h): while both of a
// ventricle's valves are shut its volume is held, the multiplier that holds it is a pressure
// that rises as the muscle tightens and falls as it relaxes, the valves open by that
// pressure, and a scene that asks for blood where there is no ventricle is refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "scene/load.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::world {
namespace {

using sim::ChamberPhase;

TEST(Blood, TheVentricleKeepsItsVolumeWhileBothValvesAreShut) {
  scene::Scene s = scene::load(test::source("scenes/heart.yaml"));
  s.output.duration_s = 2;
  World w = build_world(s);
  ASSERT_EQ(w.organs[0].model.circulation.chambers.size(), 2u);
  ASSERT_EQ(w.organs[0].model.circulation.chambers[0].name, "left_ventricle");
  double worst_drift = 0, peak_pressure = -HUGE_VAL, lowest_volume = HUGE_VAL;
  int phases_seen = 0, held_steps = 0;
  ChamberPhase last = ChamberPhase::kFilling;
  w.after_step = [&](int, const OrganBody& body) {
    const sim::ChamberState& lv = body.state.chambers[0];
    const double volume = sim::chamber_volume(body.model.circulation.chambers[0], body.state.x);
    if (sim::isovolumic(lv.phase)) {
      worst_drift = std::max(worst_drift, std::abs(volume / lv.shut_m3 - 1));
      peak_pressure = std::max(peak_pressure, lv.pressure_Pa);
      ++held_steps;
    }
    lowest_volume = std::min(lowest_volume, volume);
    if (lv.phase != last) ++phases_seen, last = lv.phase;
  };
  advance_to_frame(w, static_cast<int>(s.output.frame_count()) - 1);
  const sim::Chamber& chamber = w.organs[0].model.circulation.chambers[0];
  EXPECT_GE(phases_seen, 4) << "filling -> isovolumic contraction -> ejection -> isovolumic relaxation -> filling";
  EXPECT_GT(held_steps, 10);
  // Held to a fraction of a percent while the ventricle tightens from rest to the aortic
  // pressure and relaxes back (the shipped scenes' one iteration of a linearized constraint a
  // step).
  EXPECT_LT(worst_drift, 0.005) << "of the held volume";
  // The aortic valve opened at the aortic pressure, and the ventricle then emptied.
  EXPECT_GE(peak_pressure, chamber.afterload_Pa);
  EXPECT_LT(lowest_volume, 0.5 * chamber.rest_m3);
}

TEST(Blood, AHigherAfterloadOpensTheAorticValveLaterAndEjectsLess) {
  scene::Scene low = scene::load(test::source("scenes/heart.yaml"));
  low.output.duration_s = 2;
  scene::Scene high = low;
  high.organs[0].blood.aortic_pressure_Pa *= 2;
  auto measure = [](const scene::Scene& s, double& opens_s, double& smallest_m3) {
    World w = build_world(s);
    opens_s = NAN;
    smallest_m3 = HUGE_VAL;
    w.after_step = [&](int, const OrganBody& body) {
      const sim::ChamberState& lv = body.state.chambers[0];
      if (body.state.time_s > 0.9 && lv.phase == ChamberPhase::kEjection && std::isnan(opens_s)) opens_s = body.state.time_s;
      if (body.state.time_s > 0.9) smallest_m3 = std::min(smallest_m3, lv.volume_m3);
    };
    advance_to_frame(w, static_cast<int>(s.output.frame_count()) - 1);
  };
  double low_opens = 0, high_opens = 0, low_es = 0, high_es = 0;
  measure(low, low_opens, low_es);
  measure(high, high_opens, high_es);
  ASSERT_FALSE(std::isnan(low_opens));
  ASSERT_FALSE(std::isnan(high_opens));
  EXPECT_GT(high_opens, low_opens + 0.015) << "the ventricle needs longer to reach the higher pressure";
  EXPECT_GT(high_es, low_es * 1.05) << "and ejects less against it";
}

// A pressure pushes each face of the cavity along its normal: over the closed surface the
// forces are the pressure times the volume's gradient (and sum to nothing); with the inflow
// valve open its cap carries nothing, so the rest push towards the atrium with the pressure
// times the annulus' area.
TEST(Blood, APressureLoadsTheCavityButNotTheOpenValvesCap) {
  scene::Scene s = scene::load(test::source("scenes/heart.yaml"));
  const World w = build_world(s);
  const sim::Model& model = w.organs[0].model;
  sim::Chamber lv = model.circulation.chambers[0];
  ASSERT_LT(lv.inflow_cap.first, lv.inflow_cap.second) << "the mitral annulus' cap";
  ASSERT_FALSE(lv.chordae_points.empty()) << "the papillary muscles' wall";
  const double chordae = lv.chordae_share;
  lv.chordae_share = 0;  // All of the shut valve's load on its annulus, first.
  const Eigen::Matrix3Xd& x = model.rest_positions;
  Eigen::Matrix3Xd gradient;
  sim::chamber_volume(lv, x, gradient);
  const double pressure = 1000;
  Eigen::Matrix3Xd shut = Eigen::Matrix3Xd::Zero(3, x.cols()), filling = shut;
  sim::add_pressure_load(lv, ChamberPhase::kIsovolumicRelaxation, x, pressure, shut);
  sim::add_pressure_load(lv, ChamberPhase::kFilling, x, pressure, filling);
  EXPECT_LT((shut - pressure * gradient).norm(), 1e-9 * (pressure * gradient).norm());
  EXPECT_LT(shut.rowwise().sum().norm(), 1e-9 * shut.norm()) << "a closed surface's pressure forces cancel";
  // The cap's area: its fan of triangles from the rim's centre.
  const int rim = lv.inflow_cap.second - lv.inflow_cap.first;
  ASSERT_GT(rim, 8);
  const Eigen::Vector3d net = filling.rowwise().sum();
  EXPECT_GT(net.norm(), 0.5 * pressure * 1e-4) << "a mitral annulus of over 1 cm^2";
  EXPECT_LT(net.norm(), pressure * 2e-3) << "and under 20 cm^2";
  // The chordae move part of the shut valve's load to the wall, and create no force: the
  // closed surface's forces still cancel, and the lining pulls towards the base (the cap's
  // outward normal) where they hold it.
  lv.chordae_share = chordae;
  Eigen::Matrix3Xd held = Eigen::Matrix3Xd::Zero(3, x.cols());
  sim::add_pressure_load(lv, ChamberPhase::kEjection, x, pressure, held);
  EXPECT_LT(held.rowwise().sum().norm(), 1e-9 * held.norm());
  EXPECT_GT((held - shut).norm(), 0.1 * net.norm()) << "the chordae carry a share of the cap's load";
}

TEST(Blood, IsRefusedWhereNoVentricleHoldsIt) {
  const std::string kidney = "organs:\n  - name: kidney\n    mesh: {procedural: kidney}\n    blood: {aortic_pressure: 3 kPa}\n";
  try {
    build_world(scene::load_from_string(kidney, "scenes/test.yaml"));
    FAIL() << "blood in an organ without ventricles must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    const std::string what = e.what();
    EXPECT_NE(what.find("scenes/test.yaml:2"), std::string::npos) << what;
    EXPECT_NE(what.find("organs[0].blood: "), std::string::npos) << what;
  }
  const std::string xpbd =
      "organs:\n  - name: heart\n    mesh: {procedural: anatomical_heart, detail: 1}\n    blood: {aortic_pressure: 22 mmHg}\n"
      "solver: {method: xpbd}\n";
  try {
    build_world(scene::load_from_string(xpbd, "scenes/test.yaml"));
    FAIL() << "the blood is held by the projective solver only";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("solver.method: projective"), std::string::npos) << e.what();
  }
}

TEST(Blood, PressuresReadInMillimetresOfMercury) {
  const std::string yaml =
      "organs:\n  - name: heart\n    mesh: {procedural: anatomical_heart, detail: 1}\n"
      "    blood: {aortic_pressure: 22.5 mmHg, aortic_elastance: 0.45 mmHg/ml}\n";
  const scene::Scene s = scene::load_from_string(yaml, "scenes/test.yaml");
  EXPECT_TRUE(s.organs[0].blood.enabled);
  EXPECT_NEAR(s.organs[0].blood.aortic_pressure_Pa, 22.5 * 133.322, 1e-6);
  EXPECT_NEAR(s.organs[0].blood.aortic_elastance_Pa_per_m3, 0.45 * 133.322e6, 1e-3);
  EXPECT_FALSE(scene::load_from_string("organs:\n  - name: heart\n    mesh: {procedural: anatomical_heart}\n",
                                       "scenes/test.yaml").organs[0].blood.enabled);
}

}  // namespace
}  // namespace systole::world
