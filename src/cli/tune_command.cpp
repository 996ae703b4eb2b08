#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include "cli/command.h"
#include "common/atomic_output.h"
#include "common/error.h"
#include "scene/load.h"
#include "train/report.h"
#include "train/tune.h"
#include "train/tuned_scene.h"

namespace systole::cli {

Command add_tune_command(CLI::App& app) {
  struct Options {
    std::string scene;
    std::string output;
    std::string report;
    std::vector<std::string> defines;
    int budget = -1;
    std::uint64_t seed = 0;
    int jobs = 0;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("tune", "Fit and tune region drives to each organ's target motion; write a scene that plays them.");
  cmd->add_option("scene", o->scene, "Scene file (YAML) with a target on at least one organ")
      ->required()
      ->type_name(kSceneValue);
  cmd->add_option("-o,--output", o->output, "Tuned scene to write (YAML)")->required()->type_name(kFileValue);
  cmd->add_option("--report", o->report, "Folder for report.md and one SVG plot per region")
      ->type_name(kFolderValue);
  cmd->add_option("--budget", o->budget, "Playbacks per organ (default: the target's budget)")->check(CLI::NonNegativeNumber);
  auto* seed = cmd->add_option("--seed", o->seed, "Seed of the search (default: the scene's seed)");
  cmd->add_option("--jobs", o->jobs, "Candidates simulated at once (default: every core); same result at any count")
      ->check(CLI::PositiveNumber);
  add_define_option(*cmd, o->defines);
  return {cmd, [o, seed] {
            // The tuned scene is written with the -D values too (scene::Scene::overrides), so
            // it plays what was tuned.
            const scene::Scene scene = scene::load(o->scene, o->defines);
            // Claimed before the minutes of tuning, so a folder that is missing or read-only
            // stops the run at once rather than losing its result.
            AtomicOutput out(o->output);
            if (!o->report.empty()) std::filesystem::create_directories(o->report);
            train::TuneSettings settings;
            settings.budget = o->budget;
            settings.seed = seed->count() > 0 ? o->seed : scene.seed;
            settings.threads = o->jobs > 0 ? o->jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
            settings.log = [](const std::string& line) { std::cerr << "tune: " << line << "\n"; };
            std::vector<train::OrganTuning> tunings;
            for (std::size_t i = 0; i < scene.organs.size(); ++i) {
              if (scene.organs[i].target.enabled) tunings.push_back(train::tune_organ(scene, i, settings));
            }
            if (tunings.empty()) {
              throw Error(ExitCode::kDataError, o->scene + ": no organ has a target to tune to (add organs[].target: docs/training.md)");
            }
            {
              std::ofstream file(out.temp_path(), std::ios::binary);
              file << train::tuned_scene_yaml(scene, tunings, o->output);
              if (!file.flush()) throw Error(ExitCode::kIoError, "cannot write " + o->output);
            }
            if (!o->report.empty()) train::write_report(o->report, o->scene, tunings);
            out.commit();
            for (const auto& t : tunings) {
              std::cout << t.organ << ": RMS error " << t.before.rms_pct_of_motion << " % of the target's motion fitted -> "
                        << t.after.rms_pct_of_motion << " % tuned (as written " << t.written.rms_pct_of_motion << " %), "
                        << t.generations << " generations, "
                        << t.evaluations << " playbacks, " << t.seconds << " s\n";
            }
            std::cout << "wrote " << o->output << (o->report.empty() ? "" : " and " + o->report + "/report.md") << "\n";
            return 0;
          }};
}

}  // namespace systole::cli
