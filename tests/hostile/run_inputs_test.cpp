// ctest-labels: no-sanitizers
// The hostile-input corpus, runs (tests/hostile/README.md): a folder whose entry is a symlink
// loop, an output path that names a folder, a second run of a target being written, a scene
// in which nothing can move. Each ends with its exit code and says why, the refusals within
// 2 s of CPU time and 300 MB (wait4's rusage).

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/lock_held_elsewhere.h"
#include "support/measure.h"
#include "support/run.h"
#include "support/small_heart_clip.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTiny = {"-D", "output.width=96", "-D", "output.height=64", "-D", "output.duration=0.2 s"};

void expect_bounded(const std::string& what, const Measured& m, double cpu_s = 2.0) {
  SCOPED_TRACE(what);
  EXPECT_LT(m.cpu_s, cpu_s) << "seconds of CPU";
  EXPECT_LT(m.peak_mb, 300.0) << "MB at peak";
  std::printf("[ corpus   ] %s: exit %d, %.2f s CPU, %.0f MB peak\n", what.c_str(), m.exit_code, m.cpu_s, m.peak_mb);
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(HostileRuns, AFolderWithASymlinkLoopRendersTheRestAndExitsWithTheLoopsCode) {
  const fs::path dir = scratch("hostile_loop");
  fs::create_directories(dir / "scenes");
  write_file(dir / "scenes" / "one.yaml", small_heart_scene("duration: 0.2 s"));
  fs::create_symlink("loop.yaml", dir / "scenes" / "loop.yaml");
  fs::create_symlink("loop.glb", dir / "scenes" / "loop.glb");
  const Measured m = measure(with({"render", (dir / "scenes").string(), "-o", (dir / "out").string() + "/"}, kTiny));
  EXPECT_EQ(m.exit_code, 66) << m.errors;
  EXPECT_NE(m.errors.find("a symbolic link loop"), std::string::npos) << m.errors;
  EXPECT_TRUE(fs::exists(dir / "out" / "one.mp4")) << m.errors;
  expect_bounded("a folder with a symlink loop (one clip rendered)", m, 20.0);
}

TEST(HostileRuns, AnOutputPathEndingInASlashAfterAVideoNameIsRefused) {
  const fs::path dir = scratch("hostile_slash");
  write_file(dir / "heart.yaml", small_heart_scene("duration: 0.2 s"));
  const Measured m = measure({"render", (dir / "heart.yaml").string(), "-o", (dir / "out" / "d.mp4").string() + "/"});
  EXPECT_EQ(m.exit_code, 64) << m.errors;
  EXPECT_NE(m.errors.find("names a folder, but 'd.mp4' is a video's name"), std::string::npos) << m.errors;
  EXPECT_FALSE(fs::exists(dir / "out" / "d.mp4"));
  expect_bounded("-o out/d.mp4/", m);
}

TEST(HostileRuns, ASecondRunOfAVideoBeingWrittenIsRefusedBeforeItsSetUp) {
  const fs::path dir = scratch("hostile_busy");
  write_file(dir / "heart.yaml", small_heart_scene("duration: 0.2 s"));
  LockHeldElsewhere first(dir / "clip.mp4");  // The first run, holding the video as it renders.
  ASSERT_TRUE(first.held());
  const Measured m = measure({"render", (dir / "heart.yaml").string(), "-o", (dir / "clip.mp4").string()});
  const pid_t holder = first.pid();
  first.release();
  EXPECT_EQ(m.exit_code, 75) << m.errors;
  EXPECT_NE(m.errors.find("is being written by another run (pid " + std::to_string(holder)), std::string::npos) << m.errors;
  expect_bounded("a second run of one video", m);
}

TEST(HostileRuns, ASceneInWhichNothingCanMoveSaysSo) {
  const fs::path dir = scratch("hostile_still");
  write_file(dir / "still.yaml", "organs:\n  - name: ball\n    mesh: {procedural: heart, detail: 1}\n");
  const Measured m = measure({"motion", (dir / "still.yaml").string()});
  EXPECT_NE(m.errors.find("warning: " + (dir / "still.yaml").string() + ": nothing in this scene can move"),
            std::string::npos)
      << m.errors;
  std::printf("[ corpus   ] a scene in which nothing can move: exit %d, %.2f s CPU\n", m.exit_code, m.cpu_s);
}

}  // namespace
}  // namespace systole::test
