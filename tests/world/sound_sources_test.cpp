// The ventricles' turning points (world/sound_sources.h): found between steps on a signal
// whose turning points are known exactly, never fooled by small ringing, and on a beating
// heart at each contraction.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/load.h"
#include "world/sound_sources.h"
#include "world/world.h"

namespace systole::world {
namespace {

/// size(t) = 1 + 0.05 cos(2 pi (t - t0) / T): maxima at t0 + k T, minima half a period later.
std::vector<Sample> cosine(double t0, double period, double step, double seconds, double ripple = 0) {
  std::vector<Sample> s;
  for (double t = 0; t < seconds; t += step)
    s.push_back({t, 1 + 0.05 * std::cos(2 * std::numbers::pi * (t - t0) / period) + ripple * std::sin(2 * std::numbers::pi * 23 * t)});
  return s;
}

TEST(CycleEvents, TurningPointsAreFoundBetweenSteps) {
  const double step = 1.0 / 60, t0 = 0.2137, period = 0.8333;
  const std::vector<CycleEvent> events = detect_cycle_events(cosine(t0, period, step, 5));
  int shrink = 0, refill = 0;
  for (const CycleEvent& e : events) {
    const double phase_t = e.kind == CycleEventKind::kSystoleStart ? t0 : t0 + period / 2;
    if (e.kind == CycleEventKind::kPeakRefill) continue;
    const double k = std::round((e.time_s - phase_t) / period);
    // A parabola through three samples of a cosine 50 samples long: within 1 % of a step.
    EXPECT_NEAR(e.time_s, phase_t + k * period, 0.01 * step) << int(e.kind) << " at " << e.time_s;
    (e.kind == CycleEventKind::kSystoleStart ? shrink : refill)++;
  }
  EXPECT_EQ(shrink, 6);
  EXPECT_EQ(refill, 6);
  // The fastest refilling of a cosine is a quarter period after its minimum.
  for (const CycleEvent& e : events) {
    if (e.kind != CycleEventKind::kPeakRefill) continue;
    const double k = std::round((e.time_s - t0 - 0.75 * period) / period);
    EXPECT_NEAR(e.time_s, t0 + 0.75 * period + k * period, 0.1 * step);
  }
}

TEST(CycleEvents, SmallRingingIsNotABeat) {
  // A ripple of a tenth of the swing at 23 Hz turns the signal many times near its plateaus.
  const std::vector<CycleEvent> events = detect_cycle_events(cosine(0.3, 1.0, 1.0 / 240, 4.1, 0.005));
  int shrink = 0;
  for (const CycleEvent& e : events) shrink += e.kind == CycleEventKind::kSystoleStart;
  EXPECT_EQ(shrink, 4);
}

TEST(CycleEvents, TheBeatingHeartShrinksOnceAndRefillsOncePerBeat) {
  const scene::Scene s = scene::load(std::string(SYSTOLE_SOURCE_DIR) + "/scenes/heart.yaml", {"output.duration=3 s"});
  World w = build_world(s);
  std::vector<int> ventricles;
  for (std::size_t r = 0; r < s.organs[0].regions.size(); ++r)
    if (s.organs[0].regions[r].name.find("ventricle") != std::string::npos) ventricles.push_back(static_cast<int>(r));
  const RegionSize size(w.organs[0].model, ventricles);
  ASSERT_GT(size.particle_count(), 100);
  std::vector<Sample> samples;
  w.after_step = [&](int, const OrganBody& body) { samples.push_back({body.state.time_s, size.measure(body.state.x)}); };
  advance_to_frame(w, s.output.frame_count() - 1);
  ASSERT_EQ(samples.size(), static_cast<std::size_t>((s.output.frame_count() - 1) * w.steps_per_frame));
  int shrink = 0, refill = 0;
  for (const CycleEvent& e : detect_cycle_events(samples)) {
    std::cout << "[ event ] " << int(e.kind) << " at " << e.time_s << " s\n";
    shrink += e.kind == CycleEventKind::kSystoleStart;
    refill += e.kind == CycleEventKind::kSystoleEnd;
  }
  // 72 bpm for 3 s: 3.6 beats, each a contraction and a relaxation.
  EXPECT_GE(shrink, 3);
  EXPECT_LE(shrink, 4);
  EXPECT_GE(refill, 3);
  EXPECT_LE(refill, 4);
}

}  // namespace
}  // namespace systole::world
