#include "cli/command_line.h"

#include <string>

namespace systole::cli {

CommandLine::CommandLine() : app(std::string("Systole: ") + kSummary + ".", "systole") {
  app.set_version_flag("--version", std::string("systole ") + SYSTOLE_VERSION);
  app.require_subcommand(1);
  commands = {
      add_render_command(app), add_validate_command(app), add_compare_command(app), add_bake_command(app),
      add_info_command(app),   add_bench_command(app),    add_tune_command(app),    add_motion_command(app),
      add_export_command(app),
  };
}

}  // namespace systole::cli
