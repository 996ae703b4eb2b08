#include "scene/tree.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <unordered_map>

#include "common/error.h"

namespace systole::scene {
namespace {

Origin origin_of(const YAML::Mark& mark, const std::string& file, const Origin& fallback) {
  // yaml-cpp gives a null mark (-1) to some implicit nulls, e.g. `mass:` with no value.
  if (mark.line < 0) return fallback;
  return Origin{file, mark.line + 1, mark.column + 1};
}

/// The values converted so far and the current depth: aliases are expanded by the
/// conversion, so it is where their cost is counted.
struct Budget {
  std::size_t values = 0;
  int depth = 0;
};

Node convert(const YAML::Node& in, const std::string& file, const Origin& fallback, Budget& budget) {
  Node out;
  out.origin = origin_of(in.Mark(), file, fallback);
  if (++budget.values > kMaxSceneValues) {
    fail(out.origin, "", "the scene expands to more than " + std::to_string(kMaxSceneValues) +
                             " values; YAML aliases (*name) repeat what they name, and nested ones multiply: write the "
                             "values out, or use fewer aliases");
  }
  if (budget.depth > kMaxSceneDepth) {
    fail(out.origin, "", "lists and maps are nested more than " + std::to_string(kMaxSceneDepth) +
                             " deep; a scene needs a handful of levels");
  }
  struct Deeper {
    Budget& b;
    explicit Deeper(Budget& b) : b(b) { ++b.depth; }
    ~Deeper() { --b.depth; }
  } deeper(budget);
  switch (in.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      out.kind = Node::Kind::kNull;
      break;
    case YAML::NodeType::Scalar:
      out.kind = Node::Kind::kScalar;
      out.scalar = in.Scalar();
      break;
    case YAML::NodeType::Sequence:
      out.kind = Node::Kind::kList;
      out.flow = in.Style() == YAML::EmitterStyle::Flow;
      for (const YAML::Node& item : in) out.items.push_back(convert(item, file, out.origin, budget));
      break;
    case YAML::NodeType::Map: {
      out.kind = Node::Kind::kMap;
      out.flow = in.Style() == YAML::EmitterStyle::Flow;
      std::unordered_map<std::string, int> first_line;  // Linear in the keys, however many.
      for (const auto& kv : in) {
        const Origin key_origin = origin_of(kv.first.Mark(), file, out.origin);
        if (!kv.first.IsScalar()) {
          fail(key_origin, "", "a key must be a plain name, not " + convert(kv.first, file, key_origin, budget).describe());
        }
        const std::string key = kv.first.Scalar();
        // yaml-cpp keeps both copies of a repeated key; the second would silently win.
        const auto [first, added] = first_line.try_emplace(key, key_origin.line);
        if (!added) fail(key_origin, "", "duplicate key '" + key + "' (first written at line " + std::to_string(first->second) + ")");
        out.entries.push_back(MapEntry{key, key_origin, convert(kv.second, file, key_origin, budget)});
      }
      break;
    }
  }
  return out;
}

/// Refuses, before the parser sees it, text nested deeper than kMaxSceneDepth (the parser
/// recurses once per level and would run out of stack) - flow brackets outside quotes and
/// comments, and block levels counted as indentation steps and "- " items opened on one
/// line - and text with more than kMaxSceneValues separators (", ", ": ", "- "), which
/// cannot be a scene within the bound and would cost the parser hundreds of megabytes.
void check_shape(std::string_view text, const std::string& file) {
  int flow = 0, line = 1, column = 0;
  bool in_comment = false, at_line_start = true;
  int indent = 0, dashes = 0;
  std::size_t separators = 0;
  char quote = 0, previous = 0;
  auto too_deep = [&](int depth) {
    if (depth <= kMaxSceneDepth) return;
    fail(Origin{file, line, column + 1}, "", "lists and maps are nested more than " + std::to_string(kMaxSceneDepth) +
                                                 " deep; a scene needs a handful of levels");
  };
  for (char c : text) {
    ++column;
    const char before = previous;
    previous = c;
    if ((c == ' ' || c == '\n') && (before == ',' || before == ':' || before == '-') && !quote && !in_comment &&
        ++separators > kMaxSceneValues) {
      fail(Origin{file, line, column}, "", "has more than " + std::to_string(kMaxSceneValues) +
                                               " values; a scene needs far fewer (meshes and targets belong in files of "
                                               "their own)");
    }
    if (c == '\n') {
      ++line, column = 0, in_comment = false, at_line_start = true, indent = 0, dashes = 0;
      continue;
    }
    if (in_comment) continue;
    if (at_line_start) {
      if (c == ' ') {
        ++indent;
        continue;
      }
      if (c == '-') {
        ++dashes;
        continue;
      }
      at_line_start = false;
      // Two columns per block level is the tightest YAML allows.
      too_deep(indent / 2 + dashes);
    }
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    else if (c == '#') in_comment = true;
    else if (c == '[' || c == '{') too_deep(++flow);
    else if ((c == ']' || c == '}') && flow > 0) --flow;
  }
}

}  // namespace

const Node* Node::find(std::string_view key) const {
  for (const MapEntry& e : entries)
    if (e.key == key) return &e.value;
  return nullptr;
}

Node* Node::find(std::string_view key) {
  return const_cast<Node*>(static_cast<const Node*>(this)->find(key));
}

std::string Node::describe() const {
  switch (kind) {
    case Kind::kNull: return "nothing";
    case Kind::kList: return "a list";
    case Kind::kMap: return "a map";
    case Kind::kScalar: break;
  }
  return "\"" + scalar + "\"";
}

Node parse_yaml(std::string_view text, const std::string& origin_file) {
  if (text.size() > kMaxSceneBytes) {
    fail(Origin{origin_file, 0, 0}, "", "is " + std::to_string(text.size()) + " bytes; a scene may be at most " +
                                            std::to_string(kMaxSceneBytes) + " (meshes and targets belong in files of their own)");
  }
  check_shape(text, origin_file);
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::ParserException& e) {
    fail(Origin{origin_file, e.mark.line + 1, e.mark.column + 1}, "", "invalid YAML: " + e.msg);
  }
  Budget budget;
  return convert(root, origin_file, Origin{origin_file, 1, 1}, budget);
}

std::string where(const Origin& origin) {
  if (origin.line <= 0) return origin.file + ": ";
  return origin.file + ":" + std::to_string(origin.line) + ":" + std::to_string(origin.column) + ": ";
}

namespace {

/// The length of the valid UTF-8 sequence at text[i] (1 to 4), or 0 if none starts there.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  const std::size_t n = lead >= 0xF0 && lead <= 0xF4 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 && lead < 0xE0 ? 2 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  if (n == 3 && ((lead == 0xE0 && byte(i + 1) < 0xA0) || (lead == 0xED && byte(i + 1) >= 0xA0))) return 0;  // Overlong, surrogate.
  if (n == 4 && ((lead == 0xF0 && byte(i + 1) < 0x90) || (lead == 0xF4 && byte(i + 1) >= 0x90))) return 0;  // Overlong, > U+10FFFF.
  return n;
}

/// `text` as a terminal shows it safely: bytes that are not UTF-8, and control characters
/// but newline and tab, as \xNN (a garbage file's bytes end up in its error message).
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    const auto c = static_cast<unsigned char>(text[i]);
    if (n == 0 || (n == 1 && c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
      ++i;
      continue;
    }
    out.append(text.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace

void fail(const Origin& origin, const std::string& path, const std::string& message) {
  throw Error(ExitCode::kDataError, printable(where(origin) + (path.empty() ? "" : path + ": ") + message));
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string yaml_scalar(std::string_view text) {
  // Most names are plain words, paths and numbered copies ("heart/left_atrium", "Heart.001"):
  // plain without asking the emitter, so an atlas of thousands of parts lists fast. A letter,
  // digit or '_' first keeps out "-", "---", "...", "~"; null's spellings are the words left.
  const auto plain_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const bool simple = !text.empty() && plain_char(text.front()) &&
                      std::all_of(text.begin(), text.end(), [&](char c) { return plain_char(c) || c == '-' || c == '/' || c == '.'; });
  if (simple && text != "null" && text != "Null" && text != "NULL") return std::string(text);
  const std::string value(text);
  YAML::Emitter plain;
  plain << value;
  // The emitter quotes most text that would not read back as itself; reading it back is the
  // proof, and catches what it leaves plain (some versions write "null" or "~" bare).
  try {
    const YAML::Node back = YAML::Load(plain.c_str());
    if (plain.good() && back.IsScalar() && back.Scalar() == value) return plain.c_str();
  } catch (const YAML::Exception&) {
  }
  YAML::Emitter quoted;
  quoted << YAML::DoubleQuoted << value;
  return quoted.c_str();
}

std::string unknown_key_message(std::string_view key, const std::vector<std::string>& allowed) {
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& candidate : allowed) {
    const std::size_t d = edit_distance(key, candidate);
    if (best.empty() || d < best_distance) best = candidate, best_distance = d;
  }
  std::string message = "unknown key '" + std::string(key) + "'";
  // Up to a third of the name wrong still reads as a typo; more is a different word.
  if (!best.empty() && best_distance <= std::max<std::size_t>(2, key.size() / 3))
    message += " (did you mean '" + best + "'?)";
  message += "; allowed keys: ";
  for (std::size_t i = 0; i < allowed.size(); ++i) message += (i ? ", " : "") + allowed[i];
  return message;
}

}  // namespace systole::scene
