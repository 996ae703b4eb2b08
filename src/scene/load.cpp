#include "scene/load.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "common/input_file.h"
#include "scene/overrides.h"
#include "scene/schema.h"
#include "scene/tree.h"

namespace systole::scene {

Scene load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (const auto reason = unreadable_file_reason(file)) {
    throw Error(ExitCode::kNoInput, file.string() + ": cannot read the scene file: it is " + *reason);
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, file.string() + ": cannot open scene file: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(ExitCode::kIoError, file.string() + ": reading the scene file failed");
  return load_from_string(text.str(), file.string(), overrides);
}

Scene load_from_string(std::string_view yaml, const std::string& file_label, const std::vector<std::string>& overrides) {
  Node root = parse_yaml(yaml, file_label);
  for (const std::string& assignment : overrides) apply_override(root, assignment);
  const std::filesystem::path label(file_label);
  Scene scene = read_scene(root, label.parent_path());
  scene.path = file_label;
  scene.name = label.stem().string();
  return scene;
}

}  // namespace systole::scene
