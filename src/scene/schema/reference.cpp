// The key reference generated from the schema: docs/scenes.md embeds reference_markdown()
// (tests/scene/docs_test.cpp keeps the two in step) and -D completion uses key_paths().

#include "scene/schema.h"
#include "scene/schema/spec.h"

namespace systole::scene {
namespace {

using schema::join;

void collect_paths(const KeySpec& spec, const std::string& prefix, std::vector<std::string>& out) {
  for (const KeySpec& key : spec.keys) {
    const std::string path = join(prefix, key.name);
    out.push_back(path);
    const bool is_list = key.type.starts_with("list");
    collect_paths(key, is_list ? path + "[]" : path, out);
  }
}

// Table cells must not break the Markdown table.
std::string cell(std::string text) {
  for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2) text.replace(at, 1, "\\|");
  return text;
}

void write_tables(const KeySpec& spec, const std::string& prefix, const std::string& title, std::string& out) {
  out += "### " + title + "\n\n| Key | Type | Default | Range | Description |\n|---|---|---|---|---|\n";
  for (const KeySpec& key : spec.keys)
    out += "| `" + join(prefix, key.name) + "` | " + cell(key.type) + " | " + cell(key.default_text) + " | " +
           cell(key.range) + " | " + cell(key.doc) + " |\n";
  out += "\n";
  for (const KeySpec& key : spec.keys) {
    if (key.keys.empty()) continue;
    const bool is_list = key.type.starts_with("list");
    const std::string path = join(prefix, key.name) + (is_list ? "[]" : "");
    write_tables(key, path, "`" + path + "`", out);
  }
}

}  // namespace

std::vector<std::string> key_paths() {
  std::vector<std::string> paths;
  collect_paths(scene_schema(), "", paths);
  return paths;
}

std::string reference_markdown() {
  std::string out;
  write_tables(scene_schema(), "", "Top level", out);
  return out;
}

}  // namespace systole::scene
