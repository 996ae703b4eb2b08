#include <iostream>
#include <memory>

#include "app/summary.h"
#include "app/world.h"
#include "cli/command.h"
#include "scene/load.h"

namespace systole::cli {

void add_define_option(CLI::App& command, std::vector<std::string>& defines) {
  command.add_option("-D,--define", defines, "Override a scene value: key.path=value (repeatable)");
}

Command add_validate_command(CLI::App& app) {
  struct Options {
    std::string scene;
    std::vector<std::string> defines;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("validate", "Parse a scene and build its model; render nothing.");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required();
  add_define_option(*cmd, o->defines);
  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            const auto world = app::build_world(scene);
            std::cout << app::summarize(scene, world) << "ok\n";
            return 0;
          }};
}

}  // namespace systole::cli
