#pragma once
// The YAML document as a small tree of our own, each node remembering where it was
// written. yaml-cpp's nodes cannot carry a "came from -D" origin, and -D overrides must
// splice values into the tree before validation, so we convert once and work on this.

#include <string>
#include <string_view>
#include <vector>

#include "scene/origin.h"

namespace systole::scene {

struct MapEntry;

struct Node {
  enum class Kind { kNull, kScalar, kList, kMap };

  Kind kind = Kind::kNull;
  std::string scalar;             ///< kScalar: the text as written (quotes removed).
  std::vector<Node> items;        ///< kList
  std::vector<MapEntry> entries;  ///< kMap, in document order.
  bool flow = false;              ///< kList, kMap: written inline ([a, b], {k: v}); a scene written back keeps it.
  Origin origin;

  /// kMap: the value of `key`, or nullptr.
  const Node* find(std::string_view key) const;
  Node* find(std::string_view key);
  /// "a map", "a list", "nothing" or the quoted scalar: for "got ..." in messages.
  std::string describe() const;
};

struct MapEntry {
  std::string key;
  Origin key_origin;
  Node value;
};

/// How much a scene may be, checked while reading: YAML aliases repeat the node they name,
/// so a few hundred bytes can stand for billions of values (a "billion laughs"), and deep
/// nesting exhausts the parser's stack. The shipped scenes are far below every bound.
inline constexpr std::size_t kMaxSceneBytes = 16u << 20;    ///< A scene file or -D value. unit: bytes
inline constexpr std::size_t kMaxSceneValues = 100'000;     ///< Values, after aliases are expanded.
inline constexpr int kMaxSceneDepth = 64;                   ///< Nested lists and maps.

/// Parses YAML text; `origin_file` labels every node. A syntax error, a duplicate key, or
/// text beyond the bounds above throws Error(kDataError) with file:line:column and, for a
/// bound, which one and why it exists. Linear in the expanded size, which is bounded.
Node parse_yaml(std::string_view text, const std::string& origin_file);

/// "file:line:column: " (or "file: " when the line is unknown).
std::string where(const Origin& origin);

/// Throws Error(kDataError): "file:line:column: path: message" (path omitted when empty).
[[noreturn]] void fail(const Origin& origin, const std::string& path, const std::string& message);

/// "unknown key 'x' (did you mean 'y'?); allowed keys: a, b, c".
std::string unknown_key_message(std::string_view key, const std::vector<std::string>& allowed);

/// Levenshtein distance: how "did you mean" finds the nearest of several names.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// `text` written as a YAML scalar that reads back as exactly `text`: plain when it can be,
/// else double-quoted. How names from files are shown to be copied into a scene: a part
/// "heart/apex" reads back plain, but "Heart: left", "null" or " x" need quotes.
std::string yaml_scalar(std::string_view text);

}  // namespace systole::scene
