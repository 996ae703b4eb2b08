#include "scene/overrides.h"

#include <algorithm>
#include <cctype>

#include "scene/schema.h"

namespace systole::scene {
namespace {

void relabel(Node& node, const Origin& origin) {
  node.origin = origin;
  for (Node& item : node.items) relabel(item, origin);
  for (MapEntry& entry : node.entries) {
    entry.key_origin = origin;
    relabel(entry.value, origin);
  }
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = text.find(separator, start)) != std::string::npos; start = at + 1)
    parts.push_back(text.substr(start, at - start));
  parts.push_back(text.substr(start));
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// The item a segment names: by index, or by the item's `name` key.
std::size_t find_item(const Node& list, const std::string& segment, const Origin& origin, const std::string& path) {
  if (is_index(segment)) {
    const std::size_t index = std::stoul(segment);
    if (index >= list.items.size())
      fail(origin, path, "no item " + segment + "; the list has " + std::to_string(list.items.size()) + " item(s)");
    return index;
  }
  std::string names;
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const Node* name = list.items[i].kind == Node::Kind::kMap ? list.items[i].find("name") : nullptr;
    if (!name || name->kind != Node::Kind::kScalar) continue;
    if (name->scalar == segment) return i;
    names += (names.empty() ? "" : ", ") + name->scalar;
  }
  fail(origin, path, "no item named '" + segment + "'" + (names.empty() ? "" : "; names: " + names));
}

/// How messages name a -D: whole when short, else its start. Every node parsed from the value
/// carries this label, so a long value must not be copied into each (a 40 KB list of 20,000
/// items cost 854 MB when it was), nor echoed whole by an error.
std::string override_label(const std::string& assignment) {
  constexpr std::size_t kShown = 80;
  if (assignment.size() <= kShown) return "-D " + assignment;
  return "-D " + assignment.substr(0, kShown - 3) + "... (" + std::to_string(assignment.size()) + " characters)";
}

}  // namespace

void apply_override(Node& root, const std::string& assignment) {
  const Origin origin{override_label(assignment), 0, 0};
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    fail(origin, "", "expected key.path=value, e.g. -D organs.heart.body.mass=250g");
  const std::vector<std::string> segments = split(assignment.substr(0, equals), '.');
  if (std::any_of(segments.begin(), segments.end(), [](const std::string& s) { return s.empty(); }))
    fail(origin, "", "empty segment in key path '" + assignment.substr(0, equals) + "'");

  Node value = parse_yaml(assignment.substr(equals + 1), origin.file);
  relabel(value, origin);

  Node* node = &root;
  const KeySpec* spec = &scene_schema();
  std::string path;  // as messages spell it: organs[0].body
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string& segment = segments[i];
    const bool last = i + 1 == segments.size();
    if (node->kind == Node::Kind::kList) {
      const std::size_t index = find_item(*node, segment, origin, path);
      // Appended piecewise: g++ 12 warns falsely (-Wrestrict) on "[" + std::to_string(i).
      path += '[';
      path += std::to_string(index);
      path += ']';
      if (last) node->items[index] = std::move(value);
      else node = &node->items[index];  // a list's KeySpec already describes its items
      continue;
    }
    if (node->kind == Node::Kind::kScalar)
      fail(origin, path, "is " + node->describe() + ", which has no key '" + segment + "'");
    const KeySpec* child = spec->find(segment);
    if (!child) fail(origin, path, unknown_key_message(segment, spec->key_names()));
    if (node->kind == Node::Kind::kNull) node->kind = Node::Kind::kMap;  // `body:` with no value
    path = path.empty() ? segment : path + "." + segment;
    Node* existing = node->find(segment);
    if (last) {
      if (existing) *existing = std::move(value);
      else node->entries.push_back(MapEntry{segment, origin, std::move(value)});
      return;
    }
    if (!existing) {
      // Only maps can be created on the way: a list item would need all its required keys.
      if (child->type != "map") fail(origin, path, "is not in the scene; set the whole " + child->type + " instead");
      Node created;
      created.kind = Node::Kind::kMap;
      created.origin = origin;
      node->entries.push_back(MapEntry{segment, origin, std::move(created)});
      existing = &node->entries.back().value;
    }
    node = existing;
    spec = child;
  }
}

}  // namespace systole::scene
