#include <iostream>
#include <memory>

#include "cli/command.h"
#include "common/error.h"
#include "export/exporter.h"
#include "export/recording.h"
#include "scene/load.h"

namespace systole::cli {
namespace {

/// The scene as compact glTF needs it: its shortest loop. A scene that cannot loop is
/// refused with output.loop's own reason.
scene::Scene load_loop(const std::string& file, std::vector<std::string> defines) {
  for (const auto& d : exporter::loop_overrides()) defines.push_back(d);
  try {
    return scene::load(file, defines);
  } catch (const Error& e) {
    if (e.code() != ExitCode::kDataError) throw;
    throw Error(e.code(), std::string(e.what()) +
                              "\n(the compact glTF encoding plays whole cycles after settling, as output.loop chooses "
                              "them; export every frame instead with --encoding frames)");
  }
}

}  // namespace

void run_export(const ExportRequest& request) {
  exporter::ExportOptions options;
  options.encoding = request.encoding == "frames" ? exporter::Encoding::kFrames : exporter::Encoding::kCompact;
  options.compact.max_error_pct = exporter::parse_percent(request.max_error);
  std::vector<std::filesystem::path> loop_files, clip_files;
  for (const auto& file : request.outputs) {
    // Unknown extensions fail before anything is simulated.
    (exporter::needs_loop(exporter::file_format(file), options) ? loop_files : clip_files).push_back(file);
  }
  if (!loop_files.empty()) {
    const auto scene = load_loop(request.scene, request.defines);
    exporter::Recording rec;
    try {
      rec = exporter::record(scene, request.from_bake);
    } catch (const Error& e) {
      if (request.from_bake.empty() || e.code() != ExitCode::kDataError) throw;
      throw Error(e.code(), std::string(e.what()) +
                                "\n(a compact glTF from a bake needs a bake of the loop: systole bake SCENE -D "
                                "output.loop=true -D 'output.duration=1 ms'; or export every frame: --encoding frames)");
    }
    for (const auto& file : loop_files) std::cout << exporter::export_file(file, rec, options) << std::endl;
  }
  if (!clip_files.empty()) {
    const auto scene = scene::load(request.scene, request.defines);
    const auto rec = exporter::record(scene, request.from_bake);
    for (const auto& file : clip_files) std::cout << exporter::export_file(file, rec, options) << std::endl;
  }
}

void add_export_options(CLI::App& cmd, ExportRequest& r) {
  cmd.add_option("--encoding", r.encoding,
                 "glTF animation: compact (the loop's motion in 4-16 principal morph targets, within --max-error) or "
                 "frames (every frame a morph target: exact, large)")
      ->check(CLI::IsMember({"compact", "frames"}))
      ->default_val("compact");
  cmd.add_option("--max-error", r.max_error,
                 "compact: the error budget, RMS distance as a share of the motion (e.g. 2%)")
      ->default_val("2%");
}

Command add_export_command(CLI::App& app) {
  auto o = std::make_shared<ExportRequest>();
  auto* cmd = app.add_subcommand(
      "export", "Export the animation itself: glTF for viewers, point caches for Blender, VTK for ParaView, USD, a web page.");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required()->type_name(kSceneValue);
  cmd->add_option("-o,--output", o->outputs,
                  "File to write (repeatable), format by extension: " + exporter::known_extensions() +
                      " (default: out/<scene>.glb)")
      ->type_name(kFileValue);
  cmd->add_flag("--html", o->html, "Also write a self-contained web page that plays it (<first output>.html)");
  cmd->add_option("--from-bake", o->from_bake, "Read the positions from this bake (systole bake) instead of simulating")
      ->type_name(kFileValue);
  add_export_options(*cmd, *o);
  add_define_option(*cmd, o->defines);
  return {cmd, [o] {
            ExportRequest r = *o;
            if (r.outputs.empty()) {
              const auto scene = scene::load(r.scene, r.defines);
              r.outputs.push_back(std::filesystem::path("out") / (scene.name + ".glb"));
              std::filesystem::create_directories("out");
            }
            if (r.html) {
              auto page = r.outputs.front();
              page.replace_extension(".html");
              if (std::find(r.outputs.begin(), r.outputs.end(), page) == r.outputs.end()) r.outputs.push_back(page);
            }
            run_export(r);
            return 0;
          }};
}

}  // namespace systole::cli
