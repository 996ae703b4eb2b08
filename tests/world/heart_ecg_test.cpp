// The shipped heart, timed by its conduction system: the excitation times each
// spring's drive (atria first, ventricles after the AV node), and the world computes the
// ECG from the same excitation.

#include <gtest/gtest.h>

#include <string>

#include "scene/load.h"
#include "sim/solvers/substep.h"
#include "support/run.h"
#include "world/heart_ecg.h"
#include "world/world.h"

namespace systole::world {
namespace {

/// scenes/heart.yaml (its conduction system on), 2 s long.
scene::Scene excited_heart() {
  scene::Scene s = scene::load(test::source("scenes/heart.yaml"));
  s.output.duration_s = 2;
  return s;
}

/// The largest contraction of the springs whose end lies in `region`, at t_s.
double contraction_of(const sim::Model& model, const std::string& region, double t_s) {
  sim::State s = sim::initial_state(model);
  sim::update_contractions(model, s, t_s);
  double most = 0;
  for (int j = 0; j < model.springs.size(); ++j) {
    const int slot = model.springs.contraction_a[static_cast<std::size_t>(j)];
    const int r = model.springs.region_a[static_cast<std::size_t>(j)];
    if (r < 0 || model.regions[static_cast<std::size_t>(r)].name != region) continue;
    most = std::max(most, s.region_contraction[slot]);
  }
  return most;
}

TEST(HeartEcg, TheExcitationTimesEachSpringsDrive) {
  const World w = build_world(excited_heart());
  const sim::Model& model = w.organs[0].model;
  ASSERT_TRUE(model.excitation);
  ASSERT_GT(model.excited.size(), 20);
  const electro::Excitation& ex = *model.excitation;
  // Between the atria's excitation and the His bundle's: the atria contract, the ventricles rest.
  EXPECT_GT(contraction_of(model, "left_atrium", ex.av_node_s), 0.0);
  EXPECT_EQ(contraction_of(model, "left_ventricle", ex.his_s), 0.0);
  EXPECT_GT(contraction_of(model, "left_ventricle", ex.his_s + 0.1), 0.0);
  // The same heart with hand-timed delays (heart-cutaway's): its regions contract together from them.
  const World plain = build_world(scene::load(test::source("scenes/heart-cutaway.yaml")));
  EXPECT_FALSE(plain.organs[0].model.excitation);
  EXPECT_EQ(plain.organs[0].model.excited.size(), 0);
}

TEST(HeartEcg, TheWorldsEcgHasTwelveLeadsAtItsOwnRate) {
  const World w = build_world(excited_heart());
  const std::optional<electro::Ecg> ecg = organ_ecg(w.organs[0], 2.0);
  ASSERT_TRUE(ecg);
  EXPECT_EQ(ecg->leads.size(), 12u);
  EXPECT_EQ(ecg->samples(), 1000u);  // 2 s at 500 Hz, whatever the solver's step.
  double peak = 0;
  for (double v : *ecg->lead("II")) peak = std::max(peak, std::abs(v));
  EXPECT_GT(peak, 0.1);
  EXPECT_FALSE(organ_ecg(build_world(scene::load(test::source("scenes/heart-cutaway.yaml"))).organs[0], 2.0));
}

}  // namespace
}  // namespace systole::world
