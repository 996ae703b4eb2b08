// A scene in which nothing can move renders a still organ: scene::anything_can_move names
// what would move one (a drive, a volume drive, a motion, a poke or grab, gravity), and the
// run warns when none is there, through the command line too.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "scene/load.h"
#include "support/run.h"

namespace systole::scene {
namespace {

const std::string kOrgan = "organs:\n  - name: ball\n    mesh: {procedural: heart, detail: 1}\n";

bool can_move(const std::string& yaml) { return anything_can_move(load_from_string(yaml, "still.yaml", {})); }

TEST(StillScene, EachCauseOfMotionCounts) {
  EXPECT_FALSE(can_move(kOrgan));
  EXPECT_FALSE(can_move(kOrgan + "    regions:\n      - {name: a, select: all, drive: {waveform: sine, rate: 1 Hz, amplitude: 0}}\n"));
  EXPECT_TRUE(can_move(kOrgan + "    regions:\n      - {name: a, select: all, drive: {waveform: sine, rate: 1 Hz, amplitude: 0.1}}\n"));
  EXPECT_TRUE(can_move(kOrgan + "    body: {volume_drive: {waveform: sine, rate: 0.25 Hz, amplitude: 0.1}}\n"));
  EXPECT_TRUE(can_move(kOrgan + "gravity: [0, -9.81, 0]\n"));
  // Gravity on a body held everywhere moves nothing.
  EXPECT_FALSE(can_move(kOrgan + "    regions:\n      - {name: a, select: all, pinned: true}\ngravity: [0, -9.81, 0]\n"));
  EXPECT_TRUE(can_move(kOrgan + "    regions:\n      - {name: a, select: all, pinned: true, motion: [{time: 0 s, position: [0, 0, 0]}, "
                                "{time: 1 s, position: [0, 0.01, 0]}]}\n"));
  EXPECT_TRUE(can_move(kOrgan + "interactions:\n  - poke: {organ: ball, at: [0, 0, 0.05], force: [0, 0, -1 N]}\n"));
}

TEST(StillScene, AStillSceneIsNamedInAWarningAndStillSucceeds) {
  const auto dir = test::scratch("still_scene");
  std::ofstream(dir / "still.yaml") << kOrgan;
  const test::RunResult r = test::run(test::systole() + " validate " + (dir / "still.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("systole: warning: " + (dir / "still.yaml").string() + ": nothing in this scene can move"),
            std::string::npos)
      << r.output;
  std::ofstream(dir / "moving.yaml") << kOrgan << "gravity: [0, -9.81, 0]\n";
  const test::RunResult m = test::run(test::systole() + " validate " + (dir / "moving.yaml").string());
  EXPECT_EQ(m.exit_code, 0) << m.output;
  EXPECT_EQ(m.output.find("warning"), std::string::npos) << m.output;
}

}  // namespace
}  // namespace systole::scene
