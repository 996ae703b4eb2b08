// Batches: job lists from scenes and sweeps, shards, skip-if-done, kills and failures.

#include "batch/batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "common/error.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using batch::expand_jobs;

/// Small, short and quick to build: a batch test renders a few of these.
const std::string kTiny = " -D output.width=96 -D output.height=64 -D 'output.duration=0.2 s' -D output.antialias=0 ";

std::vector<std::string> names(const std::vector<batch::Job>& jobs) {
  std::vector<std::string> n;
  for (const auto& j : jobs) n.push_back(j.name);
  return n;
}

TEST(Sweep, SplitsOnlyTopLevelCommas) {
  using V = std::vector<std::string>;
  EXPECT_EQ(batch::split_sweep_values("60 bpm, 90 bpm,120 bpm"), (V{"60 bpm", "90 bpm", "120 bpm"}));
  EXPECT_EQ(batch::split_sweep_values("[0,1,0]"), (V{"[0,1,0]"}));
  EXPECT_EQ(batch::split_sweep_values("[0,1,0],[1, 0, 0]"), (V{"[0,1,0]", "[1, 0, 0]"}));
  EXPECT_EQ(batch::split_sweep_values("{a: 1, b: 2},x"), (V{"{a: 1, b: 2}", "x"}));
  EXPECT_EQ(batch::split_sweep_values("'a, b',\"c,d\""), (V{"'a, b'", "\"c,d\""}));
  EXPECT_EQ(batch::split_sweep_values("72 bpm"), (V{"72 bpm"}));
}

TEST(Sweep, ExpandsTheCartesianProductWithDeterministicNames) {
  const auto jobs = expand_jobs({"a/heart.yaml"}, {"organs.heart.regions.lv.drive.rate=60 bpm,90 bpm", "seed=7",
                                                   "gravity=[0,0,0],[0,-9.8,0]"});
  EXPECT_EQ(names(jobs), (std::vector<std::string>{"heart_rate-60bpm_gravity-0_0_0", "heart_rate-60bpm_gravity-0_-9.8_0",
                                                   "heart_rate-90bpm_gravity-0_0_0", "heart_rate-90bpm_gravity-0_-9.8_0"}));
  // Every job gets every -D, in command-line order, each with one value.
  EXPECT_EQ(jobs[1].overrides, (std::vector<std::string>{"organs.heart.regions.lv.drive.rate=60 bpm", "seed=7",
                                                         "gravity=[0,-9.8,0]"}));
  EXPECT_TRUE(jobs[0].swept);
  // No sweep: one job named after the scene.
  const auto one = expand_jobs({"a/heart.yaml"}, {"seed=7"});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].name, "heart");
  EXPECT_FALSE(one[0].swept);
}

TEST(Sweep, KeysThatEndAlikeAreNamedByLongerSuffixes) {
  const auto jobs = expand_jobs({"heart.yaml"}, {"organs.heart.regions.lv.drive.rate=1 Hz,2 Hz",
                                                 "organs.heart.regions.ra.drive.rate=3 Hz,4 Hz"});
  EXPECT_EQ(jobs[0].name, "heart_lv.drive.rate-1Hz_ra.drive.rate-3Hz");
}

TEST(Sweep, DuplicateNamesAndMalformedDefinesAreUsageErrors) {
  try {
    expand_jobs({"a/heart.yaml", "b/heart.yaml"}, {});
    FAIL() << "two scenes named heart";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kUsage);
    EXPECT_NE(std::string(e.what()).find("heart"), std::string::npos) << e.what();
  }
  EXPECT_THROW(expand_jobs({"heart.yaml"}, {"seed"}), Error);
  EXPECT_THROW(expand_jobs({"heart.yaml"}, {"seed=1,1"}), Error) << "two jobs named heart_seed-1";
}

TEST(Sweep, FoldersAndGlobsExpandSorted) {
  const auto dir = scratch("expand");
  for (const char* n : {"b.yaml", "a.yml", "c.yaml", "notes.txt"}) write_file(dir / n, "");
  EXPECT_EQ(names(expand_jobs({dir.string()}, {})), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(names(expand_jobs({(dir / "*.yaml").string()}, {})), (std::vector<std::string>{"b", "c"}));
  EXPECT_THROW(expand_jobs({(dir / "*.json").string()}, {}), Error);
}

TEST(Shard, ShardsPartitionTheJobListExactly) {
  const auto jobs = expand_jobs({"s.yaml"}, {"seed=1,2,3,4,5,6,7", "output.fps=24,30"});
  ASSERT_EQ(jobs.size(), 14u);
  for (int count = 1; count <= 16; ++count) {
    std::multiset<std::string> seen;
    for (int i = 0; i < count; ++i) {
      for (const auto& j : batch::select_shard(jobs, batch::parse_shard(std::to_string(i) + "/" + std::to_string(count)))) {
        seen.insert(j.name);
      }
    }
    const auto all = names(jobs);
    EXPECT_EQ(seen, std::multiset<std::string>(all.begin(), all.end())) << count << " shards";
  }
}

TEST(Shard, BadShardIsUsageError) {
  for (const char* bad : {"4/4", "-1/4", "1/0", "1", "a/b", "1/4x"}) {
    EXPECT_THROW(batch::parse_shard(bad), Error) << bad;
  }
}

batch::Shard shard_with(std::map<std::string, std::string> env) {
  return batch::shard_from_environment([env](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(Shard, ReadsSchedulerArrayVariables) {
  EXPECT_EQ(shard_with({}).count, 1);
  EXPECT_TRUE(shard_with({}).source.empty());
  auto s = shard_with({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 4);
  EXPECT_EQ(s.source, "Slurm");
  s = shard_with({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}});
  EXPECT_EQ(s.index, 3) << "--array=1-4";
  s = shard_with({{"JOB_COMPLETION_INDEX", "2"}, {"SYSTOLE_SHARD_COUNT", "5"}});
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.source, "Kubernetes");
  s = shard_with({{"AWS_BATCH_JOB_ARRAY_INDEX", "0"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "2"}});
  EXPECT_EQ(s.count, 2);
  EXPECT_EQ(s.source, "AWS Batch");
}

TEST(Shard, HalfAPairOrABadIndexIsAClearError) {
  for (const auto& env : std::vector<std::map<std::string, std::string>>{
           {{"SLURM_ARRAY_TASK_ID", "1"}},
           {{"JOB_COMPLETION_INDEX", "1"}},
           {{"AWS_BATCH_JOB_ARRAY_SIZE", "4"}},
           {{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}},
           {{"AWS_BATCH_JOB_ARRAY_INDEX", "x"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "4"}}}) {
    try {
      shard_with(env);
      FAIL() << env.begin()->first;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::kUsage);
    }
  }
  try {
    shard_with({{"JOB_COMPLETION_INDEX", "1"}});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("SYSTOLE_SHARD_COUNT"), std::string::npos) << e.what();
  }
}

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
  changed.replace(changed.find("rate: 72 bpm"), 12, "rate: 80 bpm");
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

}  // namespace
}  // namespace systole::test
