#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "batch/batch.h"
#include "batch/manifest.h"
#include "cli/command.h"
#include "clip/frame_list.h"
#include "clip/limits.h"
#include "clip/progress.h"
#include "common/error.h"
#include "scene/content_hash.h"
#include "scene/load.h"

namespace systole::cli {

void add_progress_option(CLI::App& command, std::string& progress) {
  command.add_option("--progress", progress,
                     "auto (a line on a terminal), none, or json: one object per line on stdout "
                     "({\"job\", \"frame\", \"frames\", \"fps\", \"eta_s\"}, then each job's status)")
      ->check(CLI::IsMember({"auto", "none", "json"}))
      ->default_val("auto");
}

clip::ProgressStyle progress_style(const std::string& progress) {
  if (progress == "json") return clip::ProgressStyle::kJson;
  if (progress == "none" || !clip::Progress::stderr_is_terminal()) return clip::ProgressStyle::kNone;
  return clip::ProgressStyle::kTerminal;
}

namespace {

/// What `systole render` was given.
struct RenderArgs {
  std::vector<std::string> scenes;
  std::string output, png_dir, wav, frames, from_bake, shard, progress;
  std::vector<std::string> defines;
  std::vector<std::filesystem::path> exports;  ///< --export: the animation itself beside the video.
  ExportRequest export_request;                ///< Its --encoding and --max-error.
  bool no_video = false, allow_large = false, force = false, dry_run = false;
  int jobs = 1;
};

/// --dry-run: each job of this shard, its overrides and its video, and whether it is done.
void print_plan(const std::vector<batch::Job>& jobs, const batch::BatchOptions& options) {
  for (const auto& job : jobs) {
    std::cout << job.name << "\t" << job.scene.string();
    for (const auto& o : job.overrides) std::cout << " -D '" << o << "'";
    try {
      const auto scene = scene::load(job.scene, job.overrides);
      const auto request = batch::plan_request(job, scene, options);
      std::cout << "\t-> " << (request.video.empty() ? request.png_dir : request.video).string();
      if (!request.video.empty() && options.from_bake.empty() && !options.force &&
          batch::up_to_date(request.video, {job.scene.string(), scene::scene_content_hash(scene), job.overrides,
                                          options.frames, 0})) {
        std::cout << " (up to date: skipped)";
      }
    } catch (const Error& e) {
      std::cout << "\t-> fails: " << e.what();
    }
    std::cout << "\n";
  }
}

/// Renders this shard's jobs; the exit code (a lone job's failure is thrown as its error).
int run_render(const RenderArgs& o) {
  const auto all = batch::expand_jobs(o.scenes, o.defines);
  const batch::Shard shard = o.shard.empty() ? batch::shard_from_environment() : batch::parse_shard(o.shard);
  const auto jobs = batch::select_shard(all, shard);
  batch::BatchOptions options;
  options.output = o.output;
  options.png_dir = o.png_dir;
  options.wav = o.wav;
  options.no_video = o.no_video;
  options.frames = o.frames;
  options.from_bake = o.from_bake;
  options.limits = o.allow_large ? clip::Limits::none() : clip::Limits{};
  options.progress = progress_style(o.progress);
  options.force = o.force;
  options.parallel = o.jobs;
  options.several = all.size() > 1;
  if (!shard.source.empty()) {
    std::cerr << "shard " << shard.index << "/" << shard.count << " (" << shard.source << "): " << jobs.size()
              << " of " << all.size() << " jobs\n";
  }
  if (!o.exports.empty() && all.size() != 1) {
    throw Error(ExitCode::kUsage, "--export writes one scene's animation; this render has " + std::to_string(all.size()) +
                                      " jobs (export each with systole export)");
  }
  if (o.dry_run) {
    print_plan(jobs, options);
    return 0;
  }
  // llvmpipe reads its thread count when the process (or a batch child, which inherits
  // it) creates its first context; a value the user set wins.
  ::setenv("LP_NUM_THREADS", std::to_string(batch::rasterizer_threads(jobs.size(), options)).c_str(),
           /*overwrite=*/0);
  const bool json = options.progress == clip::ProgressStyle::kJson;
  const auto results = batch::run_jobs(jobs, options, [&](const batch::JobResult& r) {
    if (json) std::cout << batch::result_json(r) << std::endl;
  });
  if (options.several) std::cerr << batch::summary_table(results);
  const int code = batch::batch_exit_code(results);
  if (code != 0 && !options.several) throw Error(static_cast<ExitCode>(code), results[0].error);
  if (code == 0 && !o.exports.empty() && !jobs.empty()) {
    // After the video: the export simulates the clip again (or reads the same bake); the
    // video's frame loop stays as it is.
    ExportRequest request = o.export_request;
    request.scene = jobs.front().scene.string();
    request.defines = jobs.front().overrides;
    request.outputs = o.exports;
    request.from_bake = o.from_bake;
    run_export(request);
  }
  return code;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Simulate and render scenes to videos (and PNG frames).");
  cmd->add_option("scene", o->scenes, "Scene files (YAML), folders of them, or glob patterns")
      ->required()
      ->type_name(kSceneValue);
  cmd->add_option("-o,--output", o->output,
                  "Video to write: .mp4 (H.264), .mkv (FFV1, lossless), .webm (VP9) or .gif (default: "
                  "output.file, else out/<scene>.<output.format>); with several jobs, a folder for <job>.<format>")
      ->type_name(kFileValue);
  cmd->add_option("--png", o->png_dir,
                  "Also write the frames as numbered PNGs (frame_00042.png) into this folder (a subfolder per "
                  "job in a batch)")
      ->type_name(kFolderValue);
  cmd->add_option("--wav", o->wav,
                  "Also write the soundtrack alone (the scene's audio:) as a 16-bit 48 kHz WAV file; with several "
                  "scenes, a folder of <job>.wav")
      ->type_name(kFileValue);
  cmd->add_flag("--no-video", o->no_video, "Write no video (with --png: frames only)");
  cmd->add_option("--frames", o->frames,
                  std::string("Render only these frames, as PNGs (needs --png; with -o also a video, if they are "
                              "consecutive). Forms: ") + clip::kFrameListForms);
  cmd->add_option("--from-bake", o->from_bake, "Read the positions from this bake (systole bake) instead of simulating")
      ->type_name(kFileValue);
  cmd->add_option("-j,--jobs", o->jobs, "Clips rendered at once, each in its own process")
      ->check(CLI::Range(1, 64))
      ->default_val(1);
  cmd->add_option("--shard", o->shard,
                  "Render only jobs k with k % N == i (0-based i/N); default: from SLURM_ARRAY_TASK_ID/COUNT, "
                  "JOB_COMPLETION_INDEX with SYSTOLE_SHARD_COUNT, or AWS_BATCH_JOB_ARRAY_INDEX/SIZE");
  cmd->add_flag("--force", o->force, "Render even when the video's manifest says it is up to date");
  cmd->add_flag("--dry-run", o->dry_run, "List the jobs and their outputs; render nothing");
  add_progress_option(*cmd, o->progress);
  add_define_option(*cmd, o->defines);
  add_allow_large_flag(*cmd, o->allow_large);
  cmd->add_option("--export", o->exports,
                  "Also export the animation itself (repeatable; .glb, .gltf, .pc2, .mdd, .pvd, .usda, .html: "
                  "systole export)")
      ->type_name(kFileValue);
  add_export_options(*cmd, o->export_request);

  return {cmd, [o] { return run_render(*o); }};
}

}  // namespace systole::cli
