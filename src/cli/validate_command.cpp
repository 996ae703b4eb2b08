#include <iostream>
#include <memory>

#include "cli/command.h"
#include "clip/camera_framing.h"
#include "clip/limits.h"
#include "clip/overlay_plan.h"
#include "scene/load.h"
#include "study/physiology.h"
#include "study/summary.h"
#include "world/frame_source.h"

namespace systole::cli {

void add_define_option(CLI::App& command, std::vector<std::string>& defines) {
  command.add_option("-D,--define", defines, "Override a scene value: key.path=value (repeatable)")
      ->type_name(kSceneKeyValue);
}

void add_allow_large_flag(CLI::App& command, bool& allow_large) {
  command.add_flag("--allow-large", allow_large,
                   "Lift the resource limits (frame size, duration, vertices, solver steps, output size: "
                   "docs/robustness.md)");
}

Command add_validate_command(CLI::App& app) {
  struct Options {
    std::string scene;
    std::vector<std::string> defines;
    bool allow_large = false;
    bool physiology = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("validate", "Parse a scene and build its model; render nothing.");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required()->type_name(kSceneValue);
  add_define_option(*cmd, o->defines);
  add_allow_large_flag(*cmd, o->allow_large);
  cmd->add_flag("--physiology", o->physiology,
                "Also simulate the generated heart and print the figures a cardiologist measures (volumes, ejection "
                "fraction, shortening, thickening, twist, valve timing) against their normal ranges (docs/anatomy.md)");
  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            // The limits `render` would apply to the default video, so a scene that passes here renders.
            const auto limits = o->allow_large ? clip::Limits::none() : clip::Limits{};
            clip::check_scene_limits(scene, {scene.output.frame_count(), true, false}, limits);
            clip::apply_to_mesh_reader(limits);
            const world::FrameSource source(scene);
            const world::World& world = source.world();
            clip::check_world_limits(scene, world, limits);
            const auto placed = clip::with_cameras_placed(scene, world);
            clip::check_organs_in_view(placed, world);
            // Resolving the overlay against the built meshes checks what only they know (a
            // volume trace's chamber), as render does.
            const clip::OverlayPlan overlay(placed, world);
            std::cout << study::summarize(placed, world);
            if (o->physiology) std::cout << study::physiology_text(study::measure_physiology(scene));
            std::cout << "ok\n";
            return 0;
          }};
}

}  // namespace systole::cli
