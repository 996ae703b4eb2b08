// The value readers shared by every table of the schema: numbers with units, words, vectors, colours.

#include "scene/schema/spec.h"

#include <cctype>

namespace systole::scene::schema {

std::string display_unit(Dimension d) {
  const DimensionInfo& info = dimension_info(d);
  return info.units.empty() ? "" : std::string(info.units[0].symbol);
}

/// Checks an SI value against a display-unit range; the message shows both.
void check_range(const Node& node, double si, Dimension d, const Range& range, const std::string& path) {
  const double shown = si / (dimension_info(d).units.empty() ? 1.0 : dimension_info(d).units[0].to_si);
  if (range.contains(shown)) return;
  const std::string as_displayed = format_quantity(si, d);
  const std::string written = node.scalar;
  // Say what the user wrote too when it was in another unit: "1500 bpm = 25 Hz".
  const bool same = written == as_displayed || written == format_number(shown);
  fail(node.origin, path, (same ? "" : written + " = ") + as_displayed + " is outside " + range.text(display_unit(d)));
}

ValueSpec<double> quantity(Dimension d, Range range) {
  ValueSpec<double> spec;
  spec.type = std::string(dimension_info(d).name);
  spec.range = range.bounded() ? range.text(display_unit(d)) : "";
  spec.read = [d, range](const Node& node, double& out, const std::string& path, const Context&) {
    const double v = parse_quantity(node, d, path);
    check_range(node, v, d, range, path);
    out = v;
  };
  spec.show = [d](const double& v) { return format_quantity(v, d); };
  return spec;
}

ValueSpec<double> number(Range range) { return quantity(Dimension::kNumber, range); }

ValueSpec<bool> boolean() {
  ValueSpec<bool> spec;
  spec.type = "boolean";
  spec.range = "`true` or `false`";
  spec.read = [](const Node& node, bool& out, const std::string& path, const Context&) {
    if (node.kind == Node::Kind::kScalar && (node.scalar == "true" || node.scalar == "True"))
      out = true;
    else if (node.kind == Node::Kind::kScalar && (node.scalar == "false" || node.scalar == "False"))
      out = false;
    else
      fail(node.origin, path, "expected true or false; got " + node.describe());
  };
  spec.show = [](const bool& v) { return v ? std::string("true") : std::string("false"); };
  return spec;
}

/// Names address list items in -D paths, so they are plain words and never all digits
/// (organs.0 must stay an index).
ValueSpec<std::string> name_text() {
  ValueSpec<std::string> spec;
  spec.type = "name";
  spec.range = "letters, digits, `_`, `-`; not only digits";
  spec.read = [](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path, "expected a name such as left_ventricle; got " + node.describe());
    const std::string& s = node.scalar;
    const bool word = std::all_of(
        s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; });
    const bool digits =
        std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (!word) fail(node.origin, path, "a name may use only letters, digits, '_' and '-'; got " + node.describe());
    if (digits)
      fail(node.origin, path,
           "a name must not be only digits (it would read as a list index in -D); got " + node.describe());
    out = s;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("—") : v; };
  return spec;
}

ValueSpec<std::string> part_text() {
  ValueSpec<std::string> spec;
  spec.type = "part name";
  spec.range = "as `systole validate` lists it";
  spec.read = [](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path,
           "expected a part's name as `systole validate` lists it, e.g. left_ventricle or heart/apex; got " +
               node.describe());
    out = node.scalar;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("—") : v; };
  return spec;
}

ValueSpec<std::string> path_text() {
  ValueSpec<std::string> spec;
  spec.type = "path";
  spec.read = [](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path, "expected a file path; got " + node.describe());
    out = node.scalar;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("—") : v; };
  return spec;
}

/// Words shown on screen (cards, captions, view titles): non-empty text of at most
/// `max_chars`; "\n" breaks a line unless `one_line`.
ValueSpec<std::string> screen_text(std::size_t max_chars, bool one_line) {
  ValueSpec<std::string> spec;
  spec.type = "text";
  spec.range = "1.." + std::to_string(max_chars) + " characters" + (one_line ? ", one line" : "");
  spec.read = [max_chars, one_line](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path,
           "expected text (quote it if it contains ': ' or starts with a symbol); got " + node.describe());
    if (node.scalar.size() > max_chars)
      fail(node.origin, path,
           "text of " + std::to_string(node.scalar.size()) + " characters is outside 1.." + std::to_string(max_chars));
    if (one_line && node.scalar.find('\n') != std::string::npos) fail(node.origin, path, "expected one line of text");
    out = node.scalar;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("—") : v; };
  return spec;
}

ValueSpec<Eigen::Vector3d> vec3(Dimension d) {
  ValueSpec<Eigen::Vector3d> spec;
  const std::string name(dimension_info(d).name);
  spec.type = d == Dimension::kNumber ? "3 numbers" : "3 " + name + "s";
  spec.read = [d, name](const Node& node, Eigen::Vector3d& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kList || node.items.size() != 3)
      fail(node.origin, path,
           "expected a list of 3 " + (d == Dimension::kNumber ? std::string("numbers") : name + "s") +
               ", e.g. [0, 1, 0]; got " +
               (node.kind == Node::Kind::kList ? std::to_string(node.items.size()) + " items" : node.describe()));
    for (int i = 0; i < 3; ++i) out[i] = parse_quantity(node.items[i], d, path + "[" + std::to_string(i) + "]");
  };
  spec.show = [d](const Eigen::Vector3d& v) {
    const std::string unit = display_unit(d);
    const double k = dimension_info(d).units.empty() ? 1.0 : dimension_info(d).units[0].to_si;
    return "[" + format_number(v.x() / k) + ", " + format_number(v.y() / k) + ", " + format_number(v.z() / k) + "]" +
           (unit.empty() ? "" : " " + unit);
  };
  return spec;
}

ValueSpec<Eigen::Vector3d> direction() {
  return vec3(Dimension::kNumber)
      .also(
          [](const Eigen::Vector3d& v) {
            return v.norm() > 1e-12 ? std::string() : std::string("expected a non-zero direction; got [0, 0, 0]");
          },
          "not [0, 0, 0]");
}

ValueSpec<Color> color() {
  ValueSpec<Color> spec;
  spec.type = "colour";
  spec.range = "`\"#rrggbb\"` or [r, g, b] in [0, 1]";
  spec.read = [](const Node& node, Color& out, const std::string& path, const Context&) {
    const std::string expected = "expected a colour: \"#rrggbb\" or [r, g, b] with channels in [0, 1]; got ";
    if (node.kind == Node::Kind::kNull)
      fail(node.origin, path, expected + "nothing (an unquoted # starts a YAML comment: write \"#b8322a\" in quotes)");
    if (node.kind == Node::Kind::kScalar) {
      const std::string& s = node.scalar;
      const bool hex = s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), [](char c) {
                         return std::isxdigit(static_cast<unsigned char>(c));
                       });
      if (!hex) fail(node.origin, path, expected + node.describe());
      for (int i = 0; i < 3; ++i) out[i] = std::stoi(s.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
      return;
    }
    if (node.kind != Node::Kind::kList || node.items.size() != 3) fail(node.origin, path, expected + node.describe());
    for (int i = 0; i < 3; ++i) {
      const std::string item_path = path + "[" + std::to_string(i) + "]";
      out[i] = parse_quantity(node.items[i], Dimension::kNumber, item_path);
      check_range(node.items[i], out[i], Dimension::kNumber, closed(0, 1), item_path);
    }
  };
  spec.show = [](const Color& c) {
    return "[" + format_number(c.x()) + ", " + format_number(c.y()) + ", " + format_number(c.z()) + "]";
  };
  return spec;
}

/// Where a key of a map was written, for cross-key messages (the map itself if absent).
const Origin& origin_of(const Node& map, const std::string& key) {
  const Node* value = map.find(key);
  return value ? value->origin : map.origin;
}

}  // namespace systole::scene::schema
