// Job lists: scenes, folders, globs and sweeps expanded into named jobs, and shards of them.

#include "batch/batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "common/error.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using batch::expand_jobs;

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

TEST(Sweep, AFolderEntryThatCannotBeReadIsAJobOfItsOwnAndOtherEntriesAreSkipped) {
  const auto dir = scratch("expand_loops");
  write_file(dir / "a.yaml", "");
  fs::create_symlink("loop.yaml", dir / "loop.yaml");  // A symlink loop: stat says ELOOP.
  fs::create_symlink("mesh.glb", dir / "mesh.glb");    // Not a scene: never looked at.
  fs::create_symlink("gone.yaml", dir / "dangling.yaml.bak");
  EXPECT_EQ(names(expand_jobs({dir.string()}, {})), (std::vector<std::string>{"a", "loop"}));
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

}  // namespace
}  // namespace systole::test
