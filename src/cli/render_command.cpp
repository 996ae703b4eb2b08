#include <filesystem>
#include <iostream>
#include <memory>

#include "app/progress.h"
#include "app/render_clip.h"
#include "cli/command.h"
#include "scene/load.h"

namespace systole::cli {

Command add_render_command(CLI::App& app) {
  struct Options {
    std::string scene, output, png_dir;
    std::vector<std::string> defines;
    bool no_video = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("render", "Simulate and render a scene to a video (and PNG frames).");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required();
  cmd->add_option("-o,--output", o->output, "Video to write (default: output.file, else out/<scene>.mp4)");
  cmd->add_option("--png", o->png_dir, "Also write every frame as a numbered PNG into this folder");
  cmd->add_flag("--no-video", o->no_video, "Write no video (with --png: frames only)");
  add_define_option(*cmd, o->defines);

  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            app::RenderRequest request;
            if (!o->no_video) {
              request.video = o->output.empty() ? app::default_video_path(scene) : std::filesystem::path(o->output);
              // The default out/ folder is ours to create; a folder the user named must
              // exist, so a typo in it is reported rather than silently created.
              if (o->output.empty() && scene.output.file.empty()) std::filesystem::create_directories("out");
            }
            request.png_dir = o->png_dir;
            request.show_progress = app::Progress::stderr_is_terminal();
            const auto times = app::render_clip(scene, request);
            if (!request.video.empty()) std::cerr << "wrote " << request.video.string() << "\n";
            if (!request.png_dir.empty()) {
              std::cerr << "wrote " << times.frames << " PNG frames to " << o->png_dir << "\n";
            }
            std::cerr << app::describe(times) << "\n";
            return 0;
          }};
}

}  // namespace systole::cli
