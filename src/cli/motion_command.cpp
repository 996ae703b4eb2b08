#include <iostream>
#include <memory>

#include "cli/command.h"
#include "common/error.h"
#include "scene/load.h"
#include "study/motion_check.h"

namespace systole::cli {
namespace {

struct MotionArgs {
  std::string scene;
  std::vector<std::string> defines;
  double duration_s = 0;
  double band_mm = 1;
  int settle_beats = 1;
  bool outside_view = false;
};

}  // namespace

Command add_motion_command(CLI::App& app) {
  auto o = std::make_shared<MotionArgs>();
  auto* cmd = app.add_subcommand("motion", "Check the simulated motion: every driven region repeats its beat, no part "
                                           "of a multi-part mesh passes through another, and a generated anatomy keeps "
                                           "its linings inside its walls. Exit 1 if not.");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required()->type_name(kSceneValue);
  add_define_option(*cmd, o->defines);
  cmd->add_option("--duration", o->duration_s, "Organ seconds to simulate (default: the scene's output.duration)")
      ->check(CLI::Range(0.1, 600.0));
  cmd->add_option("--band", o->band_mm, "How near another part a vertex is watched, in mm")
      ->check(CLI::Range(0.1, 50.0))
      ->capture_default_str();
  cmd->add_option("--settle", o->settle_beats, "Beats left out as the body leaves its rest shape")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd->add_flag("--outside-view", o->outside_view,
                "Also draw the scene's views uncut, opaque and coloured by region at every frame, and count the "
                "lining pixels of a generated anatomy they show");
  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            const study::MotionReport report =
                study::check_motion(scene, {o->duration_s, o->band_mm * 1e-3, o->settle_beats, o->outside_view});
            std::cout << study::motion_text(report);
            return report.periodic() && report.parts_kept() && report.linings_inside() ? 0
                                                                                        : static_cast<int>(ExitCode::kDiffers);
          }};
}

}  // namespace systole::cli
