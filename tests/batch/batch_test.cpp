// ctest-labels: slow-under-sanitizers
// Batches end to end, through the command line: dry runs, skip-if-done, kills and failures.

#include "batch/batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <thread>

#include "common/error.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// Small, short and quick to build: a batch test renders a few of these.
const std::string kTiny = " -D output.width=96 -D output.height=64 -D 'output.duration=0.2 s' -D output.antialias=0 ";

// ---------------------------------------------------------------------------------------
// End to end, through the command line.

/// Two copies of the heart, so a batch has two jobs of its own.
fs::path two_scenes(const std::string& name) {
  const auto dir = scratch(name);
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "out");
  const std::string heart = read_file(source("scenes/heart.yaml"));
  write_file(dir / "scenes" / "one.yaml", heart);
  write_file(dir / "scenes" / "two.yaml", heart);
  return dir;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> partial_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".partial-") != std::string::npos || name.ends_with(".lock")) found.push_back(e.path().string());
  }
  return found;
}

TEST(Batch, DryRunListsJobsAndOutputs) {
  const auto dir = two_scenes("dry_run");
  const auto r = run(systole() + " render " + (dir / "scenes").string() + kTiny + "-D 'seed=1,2' --dry-run -o " +
                     (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* job : {"one_seed-1", "one_seed-2", "two_seed-1", "two_seed-2"}) {
    EXPECT_NE(r.output.find((dir / "out" / (std::string(job) + ".mp4")).string()), std::string::npos) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir / "out")) << "nothing rendered";
}

TEST(Batch, SecondRunSkipsEverythingAndAChangedSceneRerendersOnlyItsJob) {
  const auto dir = two_scenes("skip");
  const std::string cmd = systole() + " render " + (dir / "scenes").string() + kTiny + "--progress=json -o " +
                          (dir / "out").string();
  auto r = run(cmd);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(count(r.output, "\"status\": \"done\""), 2) << r.output;
  for (const char* f : {"one.mp4", "one.mp4.json", "two.mp4", "two.mp4.json"}) EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  EXPECT_NE(r.output.find("\"frame\": 6, \"frames\": 6"), std::string::npos) << "json progress:\n" << r.output;
  const auto first_time = fs::last_write_time(dir / "out" / "one.mp4");

  r = run(cmd);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(count(r.output, "\"status\": \"skipped\""), 2) << r.output;
  EXPECT_EQ(fs::last_write_time(dir / "out" / "one.mp4"), first_time);

  std::string changed = read_file(dir / "scenes" / "two.yaml");
  // Every region's rate (the conduction system beats them at one).
  for (std::size_t at; (at = changed.find("rate: 72 bpm")) != std::string::npos;) changed.replace(at, 12, "rate: 80 bpm");
  write_file(dir / "scenes" / "two.yaml", changed);
  r = run(cmd);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(count(r.output, "\"status\": \"skipped\""), 1) << r.output;
  EXPECT_NE(r.output.find("{\"job\": \"two\", \"status\": \"done\""), std::string::npos) << r.output;

  // --force renders again; so does a changed override.
  r = run(cmd + " --force");
  EXPECT_EQ(count(r.output, "\"status\": \"done\""), 2) << r.output;
  r = run(cmd + " -D seed=3");
  EXPECT_EQ(count(r.output, "\"status\": \"done\""), 2) << r.output;
}

TEST(Batch, ABadSceneFailsAloneAndTheExitCodeSaysSo) {
  const auto dir = two_scenes("bad_scene");
  write_file(dir / "scenes" / "broken.yaml", "organs:\n  - name: heart\n    mesh: {procedural: heart}\n    bogus: 1\n");
  const auto r = run(systole() + " render " + (dir / "scenes").string() + kTiny + "--jobs 2 -o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "one.mp4")) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "two.mp4")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "broken.mp4"));
  EXPECT_NE(r.output.find("broken.yaml:4:"), std::string::npos) << "the scene's own error:\n" << r.output;
  EXPECT_NE(r.output.find("3 jobs: 2 done, 0 skipped, 1 failed"), std::string::npos) << r.output;
}

TEST(Batch, ASymlinkLoopInAFolderFailsItsJobAloneWithItsOwnExitCode) {
  const auto dir = two_scenes("symlink_loop");
  fs::create_symlink("loop.yaml", dir / "scenes" / "loop.yaml");
  fs::create_symlink("loop.glb", dir / "scenes" / "loop.glb");
  const auto alone = run(systole() + " render " + (dir / "scenes" / "loop.yaml").string() + kTiny + "-o " +
                         (dir / "alone.mp4").string());
  ASSERT_NE(alone.exit_code, 0) << alone.output;
  ASSERT_NE(alone.exit_code, 70) << "not an internal error:\n" << alone.output;
  const auto r = run(systole() + " render " + (dir / "scenes").string() + kTiny + "-o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, alone.exit_code) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "one.mp4")) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "two.mp4")) << r.output;
  EXPECT_NE(r.output.find("3 jobs: 2 done, 0 skipped, 1 failed"), std::string::npos) << r.output;
}

/// Starts `command` in the background, waits for a temporary output to appear under
/// `dir`, sends `signal` to it, and returns its exit status.
RunResult kill_mid_render(const std::string& command, const fs::path& dir, const char* signal) {
  return run("sh -c '" + command + " & pid=$!; i=0; while [ -z \"$(find " + dir.string() +
             " -name \"*.partial-*\")\" ] && [ $i -lt 400 ]; do sleep 0.02; i=$((i+1)); done; kill -" + signal +
             " $pid; wait $pid'");
}

TEST(Batch, AJobKilledMidRenderLeavesNoPartialOutputAndTheRerunCompletesIt) {
  const auto dir = two_scenes("killed");
  const std::string cmd = systole() + " render " + (dir / "scenes" / "one.yaml").string() +
                          " -D output.width=96 -D output.height=64 -D output.duration=5s -D output.antialias=0" +
                          " -o " + (dir / "out" / "one.mp4").string();
  for (const char* signal : {"TERM", "KILL"}) {
    const auto r = kill_mid_render(cmd, dir / "out", signal);
    EXPECT_NE(r.exit_code, 0) << signal << ": " << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "one.mp4")) << signal;
    EXPECT_FALSE(fs::exists(dir / "out" / "one.mp4.json")) << signal;
    // SIGTERM removes the temporary; SIGKILL cannot be caught, and leaves a hidden
    // .one.mp4.partial-<pid>-<n>.mp4 and .one.mp4.lock, never mistaken for the output.
    if (std::string(signal) == "TERM") {
      EXPECT_TRUE(partial_files(dir / "out").empty()) << r.output;
    }
  }
  const auto r = run(cmd);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(partial_files(dir / "out").empty()) << "the rerun removed what the killed run left";
  EXPECT_TRUE(fs::exists(dir / "out" / "one.mp4.json"));
  EXPECT_NE(run(cmd).output.find("up to date"), std::string::npos);
}

TEST(Batch, KillingABatchStopsItsChildrenAndRemovesTheirTemporaries) {
  const auto dir = two_scenes("killed_batch");
  const std::string cmd = systole() + " render " + (dir / "scenes").string() +
                          " -D output.width=96 -D output.height=64 -D output.duration=20s -D output.antialias=0" +
                          " --jobs 2 -o " + (dir / "out").string();
  kill_mid_render(cmd, dir / "out", "TERM");
  // The children hear of their parent's death asynchronously.
  for (int i = 0; i < 100 && !partial_files(dir / "out").empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(partial_files(dir / "out").empty());
  EXPECT_TRUE(fs::is_empty(dir / "out"));
}

TEST(Batch, AnInterruptedBatchNamesTheOutputsItHadFinished) {
  const auto dir = two_scenes("interrupted_batch");
  const fs::path log = dir / "stdout.jsonl";
  // One job at a time; once the first reports done, the batch is sent SIGTERM.
  const std::string cmd = systole() + " render " + (dir / "scenes").string() +
                          " -D output.width=96 -D output.height=64 -D output.duration=4s -D output.antialias=0" +
                          " --jobs 1 --progress json -o " + (dir / "out").string() + " > " + log.string();
  const auto r = run("sh -c '" + cmd + " & pid=$!; i=0; while ! grep -q \"status.: .done\" " + log.string() +
                     " 2>/dev/null && [ $i -lt 1000 ]; do sleep 0.02; i=$((i+1)); done; kill -TERM $pid; wait $pid'");
  EXPECT_EQ(r.exit_code, 143) << r.output;
  const std::string first = read_file(log).find("\"job\": \"one\", \"status\": \"done\"") != std::string::npos ? "one" : "two";
  EXPECT_NE(r.output.find("interrupted; written before it: '" + (dir / "out" / (first + ".mp4")).string() +
                          "'; what was being written was not"),
            std::string::npos)
      << "the batch's own message names the job it finished:\n" << r.output;
}

}  // namespace
}  // namespace systole::test
