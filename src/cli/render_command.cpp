#include <filesystem>
#include <iostream>
#include <memory>

#include "app/frame_list.h"
#include "app/progress.h"
#include "app/render_clip.h"
#include "cli/command.h"
#include "common/error.h"
#include "scene/load.h"

namespace systole::cli {

Command add_render_command(CLI::App& app) {
  struct Options {
    std::string scene, output, png_dir, frames;
    std::vector<std::string> defines;
    bool no_video = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("render", "Simulate and render a scene to a video (and PNG frames).");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required();
  cmd->add_option("-o,--output", o->output, "Video to write (default: output.file, else out/<scene>.mp4)");
  cmd->add_option("--png", o->png_dir, "Also write the frames as numbered PNGs (frame_00042.png) into this folder");
  cmd->add_flag("--no-video", o->no_video, "Write no video (with --png: frames only)");
  cmd->add_option("--frames", o->frames,
                  std::string("Render only these frames, as PNGs (needs --png; with -o also a video, if they are "
                              "consecutive). Forms: ") + app::kFrameListForms);
  add_define_option(*cmd, o->defines);

  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            app::RenderRequest request;
            if (!o->frames.empty()) {
              // A selection is for stills: a video is written only when asked for by name
              // (so a partial clip never replaces the default video), and it must be a range.
              request.frames = app::parse_frame_list(o->frames, scene.output.frame_count());
              if (o->png_dir.empty() && (o->output.empty() || o->no_video)) {
                throw Error(ExitCode::kUsage,
                            "--frames renders PNG frames: add --png DIR (and -o OUT.mp4 for a video of a "
                            "consecutive range)");
              }
              if (!o->no_video && !o->output.empty()) request.video = o->output;
            } else if (!o->no_video) {
              request.video = o->output.empty() ? app::default_video_path(scene) : std::filesystem::path(o->output);
              // The scene's output folder (out/ by default) is ours to create; a folder named
              // with -o must exist, so a typo in it is reported rather than silently created.
              if (o->output.empty() && request.video.has_parent_path()) {
                std::filesystem::create_directories(request.video.parent_path());
              }
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
