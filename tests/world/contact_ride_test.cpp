// ctest-labels: slow-under-sanitizers
// Organs that carry each other (scenes/chest.yaml, docs/contact.md "Riding the diaphragm"):
// the heart rests on the diaphragm's central tendon and the liver is pressed up under its
// right dome; neither has a scripted motion, yet both follow the breathing dome, and only
// because of contact: the same run without the two diaphragm pairs leaves them still.

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "scene/load.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::world {
namespace {

/// The heart's and the liver's centroid heights (metres), each averaged over one beat (25
/// frames at 30 fps, 0.83 s) centred on a frame.
struct Heights {
  double heart_m = 0, liver_m = 0;
};

struct Breath {
  Heights expiration, inspiration;  ///< At the dome's highest (4.286 s) and then lowest (6 s).
};

/// Runs the shipped chest through its second inspiration with only the given contact pairs
/// (the lungs and the rib cage at detail 1: neither touches the heart or the liver here,
/// so they only cost time). The first breath is left out: the heart, settling onto the
/// tendon (or, without it, onto its tethers' anchor 30 mm below), still swings then.
Breath breathe(const std::string& pairs) {
  const scene::Scene scene = scene::load(
      test::source("scenes/chest.yaml"),
      {"organs.rib_cage.mesh.detail=1", "organs.lungs.mesh.detail=1", "contact.pairs=" + pairs});
  World w = build_world(scene);
  int heart = -1, liver = -1;
  for (std::size_t i = 0; i < w.organs.size(); ++i) {
    if (w.organs[i].model.name == "heart") heart = static_cast<int>(i);
    if (w.organs[i].model.name == "liver") liver = static_cast<int>(i);
  }
  EXPECT_TRUE(heart >= 0 && liver >= 0);
  const auto centroid_y = [&](int organ) {
    Eigen::Matrix3Xd x;
    render_positions(w.organs[organ], x);
    return x.row(1).mean();
  };
  constexpr int kExpiration = 129, kInspiration = 180, kHalfBeat = 12;  // 4.286 s and 6 s at 30 fps.
  Breath b;
  for (int frame = kExpiration - kHalfBeat; frame <= kInspiration + kHalfBeat; ++frame) {
    advance_to_frame(w, frame);
    Heights* h = std::abs(frame - kInspiration) <= kHalfBeat  ? &b.inspiration
                 : std::abs(frame - kExpiration) <= kHalfBeat ? &b.expiration
                                                              : nullptr;
    if (!h) continue;
    h->heart_m += centroid_y(heart) / (2 * kHalfBeat + 1);
    h->liver_m += centroid_y(liver) / (2 * kHalfBeat + 1);
  }
  return b;
}

TEST(RidingTheDiaphragm, HeartAndLiverFollowTheDomeByContactAlone) {
  const Breath touching = breathe(
      "[{organs: [heart, diaphragm], friction: 0.3}, {organs: [liver, diaphragm], friction: 0.3}, "
      "{organs: [heart, rib_cage]}]");
  const Breath apart = breathe("[{organs: [heart, rib_cage]}]");
  const auto descent_mm = [](const Breath& b, double Heights::*organ) {
    return (b.expiration.*organ - b.inspiration.*organ) * 1000;
  };
  const double heart = descent_mm(touching, &Heights::heart_m), liver = descent_mm(touching, &Heights::liver_m);
  const double heart_apart = descent_mm(apart, &Heights::heart_m), liver_apart = descent_mm(apart, &Heights::liver_m);
  std::cout << "centroid descent from end-expiration to end-inspiration (the dome: 10 mm): heart " << heart
            << " mm, liver " << liver << " mm; without the diaphragm pairs: heart " << heart_apart << " mm, liver "
            << liver_apart << " mm\n";
  // The dome descends 10 mm; measured 7.6 mm for the heart, 4.6 for the liver.
  EXPECT_GT(heart, 5.0);
  EXPECT_GT(liver, 3.0);
  // Without contact nothing moves them with the breath: their tethers' anchors stand still.
  EXPECT_LT(std::abs(heart_apart), 1.0);
  EXPECT_LT(std::abs(liver_apart), 1.0);
}

}  // namespace
}  // namespace systole::world
