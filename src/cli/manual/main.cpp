// systole-manual: writes `man systole` and the bash and zsh completions from the command
// line's own definitions (cli/command_line.h). The build runs it (src/CMakeLists.txt); it is
// not installed.
//
//   systole-manual --out DIR --date "26 Nov 2026" --scenes-dir /usr/share/systole/scenes
//                  --docs-dir /usr/share/doc/systole
// writes DIR/man/systole.1, DIR/completion/systole (bash) and DIR/completion/_systole (zsh).

#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/command_line.h"
#include "cli/manual/completion.h"
#include "cli/manual/man_page.h"
#include "cli/manual/reference.h"
#include "common/error.h"
#include "scene/schema.h"

namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out.flush()) throw systole::Error(systole::ExitCode::kIoError, "cannot write " + file.string());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App generator{"Writes systole's man page and shell completions from its command-line definitions.",
                     "systole-manual"};
  std::string out_dir;
  systole::cli::manual::PageContext context;
  context.summary = systole::cli::kSummary;
  generator.add_option("--out", out_dir, "Folder to write man/ and completion/ into")->required();
  generator.add_option("--date", context.date, "The page's date, the release's (26 Nov 2026)")->required();
  generator.add_option("--scenes-dir", context.scenes_dir, "Where the example scenes are installed")->required();
  generator.add_option("--docs-dir", context.docs_dir, "Where the documentation is installed")->required();
  CLI11_PARSE(generator, argc, argv);

  try {
    const systole::cli::CommandLine command_line;
    const auto reference = systole::cli::manual::describe(command_line.app, SYSTOLE_VERSION);
    const auto keys = systole::scene::key_paths();
    write_text(fs::path(out_dir) / "man" / "systole.1", systole::cli::manual::man_page(reference, context));
    write_text(fs::path(out_dir) / "completion" / "systole", systole::cli::manual::bash_completion(reference, keys));
    write_text(fs::path(out_dir) / "completion" / "_systole", systole::cli::manual::zsh_completion(reference, keys));
  } catch (const std::exception& e) {
    std::cerr << "systole-manual: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
