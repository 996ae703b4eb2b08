#include <iostream>
#include <memory>

#include "cli/command.h"
#include "clip/bake.h"
#include "scene/load.h"

namespace systole::cli {

Command add_bake_command(CLI::App& app) {
  struct Options {
    std::string scene, output, progress;
    std::vector<std::string> defines;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "bake", "Simulate a scene and save every frame's positions, to render frame ranges apart (render --from-bake).");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required()->type_name(kSceneValue);
  cmd->add_option("-o,--output", o->output, "Bake file to write (default: out/<scene>.bake)")
      ->type_name(kFileValue);
  add_progress_option(*cmd, o->progress);
  add_define_option(*cmd, o->defines);
  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            std::filesystem::path file = o->output;
            if (file.empty()) {
              file = std::filesystem::path("out") / (scene.name + ".bake");
              std::filesystem::create_directories(file.parent_path());
            }
            const double wall_s = clip::bake_clip(scene, file, progress_style(o->progress), scene.name);
            std::cerr << "wrote " << file.string() << " (" << scene.output.frame_count() << " frames, "
                      << std::filesystem::file_size(file) / 1e6 << " MB) in " << wall_s << " s\n";
            return 0;
          }};
}

}  // namespace systole::cli
