#include <iostream>

#include "cli/command.h"
#include "study/info.h"

namespace systole::cli {

Command add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Versions, GL renderer and available encoders.");
  return {cmd, [] {
            std::cout << study::system_info();
            return 0;
          }};
}

}  // namespace systole::cli
