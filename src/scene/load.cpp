#include "scene/load.h"

#include <cerrno>
#include <cstring>
#include <cstdint>
#include <fstream>
#include <string>

#include "common/error.h"
#include "common/input_file.h"
#include "scene/overrides.h"
#include "scene/schema.h"
#include "scene/tree.h"

namespace systole::scene {

namespace {

/// `size`: the file's size, as the system gives it ("4294967296 bytes"), or as far as it was read ("over ...").
[[noreturn]] void too_large(const std::filesystem::path& file, const std::string& size) {
  fail(Origin{file.string(), 0, 0}, "",
       "is " + size + " bytes; a scene may be at most " + std::to_string(kMaxSceneBytes) +
           " (meshes and targets belong in files of their own)");
}

/// The scene file's text. Its size is checked before reading, and at most one chunk past
/// the limit is ever read (a file that grows, or one whose size the system does not know),
/// so a huge file costs neither its size in memory nor the time to read it.
std::string read_scene_text(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxSceneBytes) too_large(file, std::to_string(size));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, file.string() + ": cannot open scene file: " + std::strerror(errno));
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes) too_large(file, "over " + std::to_string(kMaxSceneBytes));
  }
  if (in.bad()) throw Error(ExitCode::kIoError, file.string() + ": reading the scene file failed");
  return text;
}

}  // namespace

Scene load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (const auto reason = unreadable_file_reason(file)) {
    throw Error(ExitCode::kNoInput, file.string() + ": cannot read the scene file: it is " + *reason);
  }
  return load_from_string(read_scene_text(file), file.string(), overrides);
}

Scene load_from_string(std::string_view yaml, const std::string& file_label, const std::vector<std::string>& overrides) {
  Node root = parse_yaml(yaml, file_label);
  for (const std::string& assignment : overrides) apply_override(root, assignment);
  const std::filesystem::path label(file_label);
  Scene scene = read_scene(root, label.parent_path());
  scene.path = file_label;
  scene.overrides = overrides;
  scene.name = label.stem().string();
  return scene;
}

}  // namespace systole::scene
