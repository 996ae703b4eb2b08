// systole: the command line. A thin layer over app/: it parses arguments, maps errors to
// exit codes and is the only place that exits.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/info.h"
#include "app/progress.h"
#include "app/render_clip.h"
#include "app/summary.h"
#include "app/world.h"
#include "common/atomic_output.h"
#include "common/error.h"
#include "scene/load.h"

namespace {

using systole::Error;
using systole::ExitCode;

/// SIGINT / SIGTERM: remove every temporary output (earlier outputs were never touched)
/// and exit with 128 + signal, as shells expect.
extern "C" void on_interrupt(int sig) {
  systole::remove_pending_outputs_signal_safe();
  static const char msg[] = "\nsystole: interrupted; no output was written\n";
  [[maybe_unused]] auto n = ::write(STDERR_FILENO, msg, sizeof msg - 1);
  ::_exit(128 + sig);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int run_render(const std::string& scene_path, const std::vector<std::string>& defines, const std::string& output,
               const std::string& png_dir, bool no_video) {
  const auto scene = systole::scene::load(scene_path, defines);
  systole::app::RenderRequest request;
  if (!no_video) {
    request.video = output.empty() ? systole::app::default_video_path(scene) : std::filesystem::path(output);
    // The default out/ folder is ours to create; a folder the user named must exist, so a
    // typo in it is reported rather than silently created.
    if (output.empty() && scene.output.file.empty()) std::filesystem::create_directories("out");
  }
  request.png_dir = png_dir;
  request.show_progress = systole::app::Progress::stderr_is_terminal();
  const auto times = systole::app::render_clip(scene, request);
  if (!request.video.empty()) std::cerr << "wrote " << request.video.string() << "\n";
  if (!request.png_dir.empty()) std::cerr << "wrote " << times.frames << " PNG frames to " << png_dir << "\n";
  std::cerr << systole::app::describe(times) << "\n";
  return 0;
}

int run_validate(const std::string& scene_path, const std::vector<std::string>& defines) {
  const auto scene = systole::scene::load(scene_path, defines);
  const auto world = systole::app::build_world(scene);
  std::cout << systole::app::summarize(scene, world) << "ok\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  install_signal_handlers();
  CLI::App cli{"Systole: self-driven soft-body organ animations, from a YAML scene to a video."};
  cli.set_version_flag("--version", std::string("systole ") + SYSTOLE_VERSION);
  cli.require_subcommand(1);

  std::string scene_path, output, png_dir;
  std::vector<std::string> defines;
  bool no_video = false;

  auto* render = cli.add_subcommand("render", "Simulate and render a scene to a video (and PNG frames).");
  render->add_option("scene", scene_path, "Scene file (YAML)")->required();
  render->add_option("-o,--output", output, "Video to write (default: output.file, else out/<scene>.mp4)");
  render->add_option("--png", png_dir, "Also write every frame as a numbered PNG into this folder");
  render->add_flag("--no-video", no_video, "Write no video (with --png: frames only)");
  render->add_option("-D,--define", defines, "Override a scene value: key.path=value (repeatable)");

  auto* validate = cli.add_subcommand("validate", "Parse a scene and build its model; render nothing.");
  validate->add_option("scene", scene_path, "Scene file (YAML)")->required();
  validate->add_option("-D,--define", defines, "Override a scene value: key.path=value (repeatable)");

  auto* info = cli.add_subcommand("info", "Versions, GL renderer and available encoders.");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::kUsage);
  }

  try {
    if (render->parsed()) return run_render(scene_path, defines, output, png_dir, no_video);
    if (validate->parsed()) return run_validate(scene_path, defines);
    if (info->parsed()) {
      std::cout << systole::app::system_info();
      return 0;
    }
  } catch (const Error& e) {
    std::cerr << "systole: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "systole: internal error: " << e.what() << "\n";
    return static_cast<int>(ExitCode::kInternal);
  }
  return static_cast<int>(ExitCode::kUsage);
}
