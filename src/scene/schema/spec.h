#pragma once
// The schema's building blocks. A ValueSpec<Out> reads one YAML node into an Out and
// describes itself (type, range, default, keys); a Field<T> binds a ValueSpec to one key of
// struct T. Tables of Fields, one per scene struct, make the schema (organ.cpp, world.cpp,
// output.cpp, overlay.cpp, scene.cpp); reference.cpp turns them into docs/scenes.md.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/error.h"
#include "scene/schema.h"
#include "scene/units.h"

namespace systole::scene::schema {

struct Context {
  std::filesystem::path base_dir;  ///< Scene folder: relative mesh files start here.
};

inline std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

template <class Out>
struct ValueSpec {
  std::string type;
  std::string range;
  std::vector<KeySpec> keys;
  std::function<void(const Node&, Out&, const std::string& path, const Context&)> read;
  std::function<std::string(const Out&)> show;  ///< A value as the docs' default column shows it.

  /// Adds a rule checked after reading: `check` returns an error message, or "" when fine.
  ValueSpec also(std::function<std::string(const Out&)> check, std::string range_text) const {
    ValueSpec spec = *this;
    spec.range = std::move(range_text);
    spec.read = [inner = read, check](const Node& node, Out& out, const std::string& path, const Context& ctx) {
      inner(node, out, path, ctx);
      if (std::string problem = check(out); !problem.empty()) fail(node.origin, path, problem);
    };
    return spec;
  }
};

template <class T>
struct Field {
  KeySpec spec;
  bool is_required = false;
  std::function<void(const Node&, T&, const std::string& path, const Context&)> read;

  Field required() const {
    Field f = *this;
    f.is_required = true;
    f.spec.default_text = "required";
    return f;
  }
  /// For defaults that read better as words or exact fractions than as numbers.
  Field shown_default(std::string text) const {
    Field f = *this;
    f.spec.default_text = std::move(text);
    return f;
  }
};

/// A key bound through an accessor (T& -> M&), for keys that also set a flag or a kind.
template <class T, class M>
Field<T> field(std::string name, ValueSpec<M> value, std::type_identity_t<std::function<M&(T&)>> access,
               std::string doc) {
  T defaults{};
  KeySpec spec{std::move(name), value.type, value.show(access(defaults)), value.range, std::move(doc), value.keys};
  return Field<T>{std::move(spec), false,
                  [value, access](const Node& node, T& out, const std::string& path, const Context& ctx) {
                    value.read(node, access(out), path, ctx);
                  }};
}

/// A key bound to a member; its default is the member's default in scene.h.
template <class T, class M>
Field<T> field(std::string name, ValueSpec<M> value, M T::*member, std::string doc) {
  return field<T, M>(
      std::move(name), std::move(value), [member](T& t) -> M& { return t.*member; }, std::move(doc));
}

// --- Numbers -----------------------------------------------------------------------------

/// An interval in the dimension's display unit (deg for angles): [lo, hi], ( ) when open.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
  bool bounded() const { return std::isfinite(lo) || std::isfinite(hi); }
  std::string text(const std::string& unit) const {
    if (!bounded()) return "";
    std::string t = std::string(lo_open ? "(" : "[") + (std::isfinite(lo) ? format_number(lo) : "-inf") + ", " +
                    (std::isfinite(hi) ? format_number(hi) : "inf") + (hi_open ? ")" : "]");
    return unit.empty() ? t : t + " " + unit;
  }
};

inline Range closed(double lo, double hi) { return {lo, hi, false, false}; }
inline Range open_closed(double lo, double hi) { return {lo, hi, true, false}; }
inline Range open(double lo, double hi) { return {lo, hi, true, true}; }
inline Range any() { return {}; }

std::string display_unit(Dimension d);
/// Checks an SI value against a display-unit range; the message shows both.
void check_range(const Node& node, double si, Dimension d, const Range& range, const std::string& path);
ValueSpec<double> quantity(Dimension d, Range range);
ValueSpec<double> number(Range range);

template <class I>
ValueSpec<I> whole(std::int64_t lo, std::int64_t hi) {
  ValueSpec<I> spec;
  spec.type = "whole number";
  spec.range = hi == std::numeric_limits<std::int64_t>::max() ? std::to_string(lo) + " or more"
                                                              : std::to_string(lo) + ".." + std::to_string(hi);
  spec.read = [lo, hi](const Node& node, I& out, const std::string& path, const Context&) {
    const std::int64_t v = parse_integer(node, path);
    if (v < lo || v > hi)
      fail(node.origin, path, std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    out = static_cast<I>(v);
  };
  spec.show = [](const I& v) { return std::to_string(v); };
  return spec;
}

ValueSpec<bool> boolean();

// --- Words -------------------------------------------------------------------------------

/// Names address list items in -D paths, so they are plain words and never all digits
/// (organs.0 must stay an index).
ValueSpec<std::string> name_text();
/// A part of a mesh, as `systole validate` lists it: any text, since a file's author names
/// its parts freely ("heart/left_atrium", "Heart.001", "Armature|Valve"). It is only ever a
/// value, never a -D path segment or a label (a batch that sweeps it cleans it for the job's
/// name), so nothing downstream restricts it.
ValueSpec<std::string> part_text();
ValueSpec<std::string> path_text();
/// Words shown on screen (cards, captions, view titles): non-empty text of at most
/// `max_chars`; "\n" breaks a line unless `one_line`.
ValueSpec<std::string> screen_text(std::size_t max_chars, bool one_line);

template <class E>
ValueSpec<E> choice(std::vector<std::pair<std::string, E>> options) {
  ValueSpec<E> spec;
  spec.type = "one of";
  std::vector<std::string> names;
  for (const auto& [name, value] : options) {
    spec.range += (spec.range.empty() ? "`" : ", `") + name + "`";
    names.push_back(name);
  }
  spec.read = [options, names](const Node& node, E& out, const std::string& path, const Context&) {
    if (node.kind == Node::Kind::kScalar)
      for (const auto& [name, value] : options)
        if (node.scalar == name) {
          out = value;
          return;
        }
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    fail(node.origin, path, "expected one of " + list + "; got " + node.describe());
  };
  spec.show = [options](const E& v) {
    for (const auto& [name, value] : options)
      if (value == v) return name;
    return std::string("—");
  };
  return spec;
}

// --- Vectors, colours and lists ----------------------------------------------------------

ValueSpec<Eigen::Vector3d> vec3(Dimension d);
ValueSpec<Eigen::Vector3d> direction();
ValueSpec<Color> color();

template <class T>
ValueSpec<std::vector<T>> list(ValueSpec<T> item, std::size_t min, std::size_t max, std::string type) {
  ValueSpec<std::vector<T>> spec;
  spec.type = std::move(type);
  spec.range = max == std::numeric_limits<std::size_t>::max()
                   ? (min > 0 ? "at least " + std::to_string(min) + " item" + (min > 1 ? "s" : "") : "")
                   : std::to_string(min) + ".." + std::to_string(max) + " items";
  spec.keys = item.keys;
  spec.read = [item, min, max, type = spec.type](const Node& node, std::vector<T>& out, const std::string& path,
                                                 const Context& ctx) {
    if (node.kind != Node::Kind::kList && node.kind != Node::Kind::kNull)
      fail(node.origin, path, "expected a " + type + " (a YAML sequence); got " + node.describe());
    const std::size_t n = node.items.size();
    if (n < min || n > max) {
      const std::string expected = max == std::numeric_limits<std::size_t>::max()
                                       ? "at least " + std::to_string(min)
                                       : std::to_string(min) + ".." + std::to_string(max);
      fail(node.origin, path, "expected " + expected + " items; got " + std::to_string(n));
    }
    out.clear();
    for (std::size_t i = 0; i < n; ++i) {
      T value{};
      item.read(node.items[i], value, path + "[" + std::to_string(i) + "]", ctx);
      out.push_back(std::move(value));
    }
  };
  spec.show = [](const std::vector<T>& v) { return v.empty() ? std::string("[]") : std::string("—"); };
  return spec;
}

template <class T>
using Check = std::function<void(const Node&, T&, const std::string& path, const Context&)>;

/// A map of known keys. Unknown keys are errors (with the closest allowed key), required
/// keys must be present, and `check` runs last for rules across keys.
template <class T>
ValueSpec<T> map(std::vector<Field<T>> fields, Check<T> check = nullptr) {
  ValueSpec<T> spec;
  spec.type = "map";
  for (const Field<T>& f : fields) spec.keys.push_back(f.spec);
  spec.read = [fields, check](const Node& node, T& out, const std::string& path, const Context& ctx) {
    std::vector<std::string> allowed;
    for (const Field<T>& f : fields) allowed.push_back(f.spec.name);
    auto list_allowed = [&] {
      std::string s;
      for (const std::string& a : allowed) s += (s.empty() ? "" : ", ") + a;
      return s;
    };
    // `body:` with nothing after it is an empty map: every key keeps its default.
    if (node.kind != Node::Kind::kMap && node.kind != Node::Kind::kNull)
      fail(node.origin, path, "expected a map with keys " + list_allowed() + "; got " + node.describe());
    for (const MapEntry& entry : node.entries) {
      const auto f =
          std::find_if(fields.begin(), fields.end(), [&](const Field<T>& x) { return x.spec.name == entry.key; });
      if (f == fields.end()) fail(entry.key_origin, path, unknown_key_message(entry.key, allowed));
    }
    for (const Field<T>& f : fields) {
      if (const Node* value = node.find(f.spec.name))
        f.read(*value, out, join(path, f.spec.name), ctx);
      else if (f.is_required)
        fail(node.origin, path, "missing required key '" + f.spec.name + "' (" + f.spec.doc + ")");
    }
    if (check) check(node, out, path, ctx);
  };
  spec.show = [](const T&) { return std::string(); };
  return spec;
}

/// Where a key of a map was written, for cross-key messages (the map itself if absent).
const Origin& origin_of(const Node& map, const std::string& key);

}  // namespace systole::scene::schema
