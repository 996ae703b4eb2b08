#pragma once
// Batches: many scenes, sweeps of -D values, shards across machines, skip-if-done, several
// clips at once, each failure isolated. render_clip() renders one clip; this module decides
// which clips, where they go, and runs them. docs/batch.md is the user's guide.
//
// Inputs:  scene files, folders and glob patterns; -D key=value and key=v1,v2,... sweeps;
//          a shard (--shard i/N or a scheduler's array variables).
// Outputs: one video per job (<name>.mp4), its manifest (<video>.json), a summary table.
// See also: app/manifest.h (skip-if-done), app/render_clip.h (one clip), app/bake.h.

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "clip/limits.h"
#include "clip/progress.h"
#include "clip/render_clip.h"
#include "scene/scene.h"

namespace systole::batch {

/// Splits a -D value into sweep values at commas outside brackets ([], {}, ()) and quotes
/// ('...', "..."), trimming spaces: "60 bpm,90 bpm" gives two values, "[0,1,0]" one, and
/// "[0,1,0],[1,0,0]" two. A value with a comma of its own is quoted: 'label="a, b"'.
std::vector<std::string> split_sweep_values(std::string_view value);

/// One clip to render.
struct Job {
  std::string name;                    ///< Unique in the batch; names the video and progress.
  std::filesystem::path scene;
  std::vector<std::string> overrides;  ///< key=value for scene::load, in command-line order.
  bool swept = false;                  ///< Its name carries sweep values (then so does its video).
};

/// Expands scenes and sweeps into the job list, in a fixed order: scenes as given (a
/// folder's *.yaml/*.yml and a glob's matches sorted by name), and for each scene the
/// cartesian product of the sweeps, the first swept -D varying slowest. A job's name is
/// the scene's stem, then `_<key>-<value>` per swept key: <key> is the last segment of its
/// path (more segments when two swept keys end alike), <value> keeps [A-Za-z0-9.+-], drops
/// spaces, quotes and brackets, and turns anything else into '_': `heart_rate-90bpm`.
/// Throws Error(kUsage) when two jobs get the same name or a -D has no '=', and
/// Error(kNoInput) when a folder or pattern holds no scene.
std::vector<Job> expand_jobs(const std::vector<std::string>& scenes, const std::vector<std::string>& defines);

/// This task's share of the job list: jobs k with k % count == index.
struct Shard {
  int index = 0;       ///< 0-based.
  int count = 1;
  std::string source;  ///< "--shard", "Slurm", "Kubernetes", "AWS Batch"; empty: no sharding.
};

/// "i/N" with 0 <= i < N. Throws Error(kUsage) otherwise.
Shard parse_shard(const std::string& text);

/// Reads a scheduler's array index and count: Slurm (SLURM_ARRAY_TASK_ID minus
/// SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_COUNT), Kubernetes Indexed Jobs
/// (JOB_COMPLETION_INDEX with SYSTOLE_SHARD_COUNT, since Kubernetes passes no count), AWS
/// Batch (AWS_BATCH_JOB_ARRAY_INDEX, AWS_BATCH_JOB_ARRAY_SIZE). None set: no sharding.
/// Throws Error(kUsage) when only half of a pair is set or a value is not a valid index.
using Environment = std::function<const char*(const char*)>;
Shard shard_from_environment(const Environment& getenv = [](const char* n) { return std::getenv(n); });

/// The jobs of `shard`, in order.
std::vector<Job> select_shard(const std::vector<Job>& jobs, const Shard& shard);

/// How every job of a batch renders (the command line's options).
struct BatchOptions {
  std::filesystem::path output;   ///< -o: a video for one job; a folder for several (or when it is one).
  std::filesystem::path png_dir;  ///< --png: frames; with several jobs, one subfolder per job.
  std::filesystem::path wav;      ///< --wav: the soundtrack alone; with several jobs, <folder>/<job>.wav.
  bool no_video = false;
  std::string frames;             ///< --frames list; empty: the whole clip.
  std::filesystem::path from_bake;
  clip::Limits limits;
  clip::ProgressStyle progress = clip::ProgressStyle::kNone;
  bool force = false;             ///< Render even when the manifest says the video is up to date.
  int parallel = 1;               ///< Jobs at once (--jobs), each in its own process.
  bool several = false;           ///< The batch (before sharding) has more than one job.
};

/// What render_clip is asked for one job, once its scene is loaded. A swept job's default
/// video is <scene's output folder>/<job name>.mp4; otherwise the scene's own default.
clip::RenderRequest plan_request(const Job& job, const scene::Scene& scene, const BatchOptions& options);

struct JobResult {
  enum class Status { kDone, kSkipped, kFailed };
  std::string job;
  Status status = Status::kFailed;
  double wall_s = 0;   ///< unit: s
  std::string output;  ///< The video (or PNG folder) written or skipped.
  std::string error;   ///< kFailed: the message.
  int exit_code = 0;   ///< kFailed: what the job alone would exit with.
};

/// Loads, plans, skips when up to date (app/manifest.h) or renders, and writes the
/// manifest. Never throws: a failure is a kFailed result carrying the message and code.
JobResult run_job(const Job& job, const BatchOptions& options);

/// llvmpipe's rasterizer threads for each render of this run: the cores, shared among the
/// jobs rendered at once in their own processes. A big mesh's clip waits on the rasterizer
/// (the 163k-triangle atlas heart at 720p: 14.4 s with one thread, 12.2 s with two), and the
/// generated heart's balanced stages lose nothing measurable to the contention (6.9 s and
/// 7.0 s; docs/performance.md). llvmpipe reads them
/// (LP_NUM_THREADS) when a process creates its first context, so the command line sets the
/// environment from this before run_jobs forks (a value the user set wins); the library never does.
int rasterizer_threads(std::size_t job_count, const BatchOptions& options);

/// Runs the jobs, options.parallel at a time. One job alone runs in this process; a batch
/// runs each job in a child process, so a crash fails only its job and killing the batch
/// (SIGINT/SIGTERM) stops the children, which remove their temporaries. `on_done` is called
/// in this process as each job ends.
std::vector<JobResult> run_jobs(const std::vector<Job>& jobs, const BatchOptions& options,
                                const std::function<void(const JobResult&)>& on_done);

/// One line per job (status, wall time, output or error) and a count of each status.
std::string summary_table(const std::vector<JobResult>& results);

/// {"job": ..., "status": ..., "wall_s": ..., "output": ..., "error": ...}
std::string result_json(const JobResult& result);

/// 0 when nothing failed, else the exit code of the first failed job.
int batch_exit_code(const std::vector<JobResult>& results);

}  // namespace systole::batch
