#include "scene/schema.h"

#include <Eigen/Geometry>  // cross()
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>

#include "common/error.h"
#include "scene/units.h"

namespace systole::scene {
namespace {

// ---------------------------------------------------------------------------------------
// Building blocks. A ValueSpec<Out> reads one YAML node into an Out and describes itself;
// a Field<T> binds a ValueSpec to one key of struct T. Tables of Fields make the schema.

struct Context {
  std::filesystem::path base_dir;  ///< Scene folder: relative mesh files start here.
};

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

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
  return field<T, M>(std::move(name), std::move(value), [member](T& t) -> M& { return t.*member; }, std::move(doc));
}

// --- Numbers -----------------------------------------------------------------------------

/// An interval in the dimension's display unit (deg for angles): [lo, hi], ( ) when open.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  bool bounded() const { return std::isfinite(lo) || std::isfinite(hi); }
  std::string text(const std::string& unit) const {
    if (!bounded()) return "";
    std::string t = std::string(lo_open ? "(" : "[") + (std::isfinite(lo) ? format_number(lo) : "-inf") + ", " +
                    (std::isfinite(hi) ? format_number(hi) : "inf") + (hi_open ? ")" : "]");
    return unit.empty() ? t : t + " " + unit;
  }
};

Range closed(double lo, double hi) { return {lo, hi, false, false}; }
Range open_closed(double lo, double hi) { return {lo, hi, true, false}; }
Range open(double lo, double hi) { return {lo, hi, true, true}; }
Range any() { return {}; }

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

ValueSpec<bool> boolean() {
  ValueSpec<bool> spec;
  spec.type = "boolean";
  spec.range = "`true` or `false`";
  spec.read = [](const Node& node, bool& out, const std::string& path, const Context&) {
    if (node.kind == Node::Kind::kScalar && (node.scalar == "true" || node.scalar == "True")) out = true;
    else if (node.kind == Node::Kind::kScalar && (node.scalar == "false" || node.scalar == "False")) out = false;
    else fail(node.origin, path, "expected true or false; got " + node.describe());
  };
  spec.show = [](const bool& v) { return v ? std::string("true") : std::string("false"); };
  return spec;
}

// --- Words -------------------------------------------------------------------------------

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
    const bool word = std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; });
    const bool digits = std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (!word) fail(node.origin, path, "a name may use only letters, digits, '_' and '-'; got " + node.describe());
    if (digits) fail(node.origin, path, "a name must not be only digits (it would read as a list index in -D); got " + node.describe());
    out = s;
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
      fail(node.origin, path, "expected text (quote it if it contains ': ' or starts with a symbol); got " + node.describe());
    if (node.scalar.size() > max_chars)
      fail(node.origin, path, "text of " + std::to_string(node.scalar.size()) + " characters is outside 1.." + std::to_string(max_chars));
    if (one_line && node.scalar.find('\n') != std::string::npos) fail(node.origin, path, "expected one line of text");
    out = node.scalar;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("—") : v; };
  return spec;
}

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

ValueSpec<Eigen::Vector3d> vec3(Dimension d) {
  ValueSpec<Eigen::Vector3d> spec;
  const std::string name(dimension_info(d).name);
  spec.type = d == Dimension::kNumber ? "3 numbers" : "3 " + name + "s";
  spec.read = [d, name](const Node& node, Eigen::Vector3d& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kList || node.items.size() != 3)
      fail(node.origin, path, "expected a list of 3 " + (d == Dimension::kNumber ? std::string("numbers") : name + "s") +
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
  return vec3(Dimension::kNumber).also(
      [](const Eigen::Vector3d& v) { return v.norm() > 1e-12 ? std::string() : std::string("expected a non-zero direction; got [0, 0, 0]"); },
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
      const bool hex = s.size() == 7 && s[0] == '#' &&
                       std::all_of(s.begin() + 1, s.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
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
      const auto f = std::find_if(fields.begin(), fields.end(), [&](const Field<T>& x) { return x.spec.name == entry.key; });
      if (f == fields.end()) fail(entry.key_origin, path, unknown_key_message(entry.key, allowed));
    }
    for (const Field<T>& f : fields) {
      if (const Node* value = node.find(f.spec.name)) f.read(*value, out, join(path, f.spec.name), ctx);
      else if (f.is_required) fail(node.origin, path, "missing required key '" + f.spec.name + "' (" + f.spec.doc + ")");
    }
    if (check) check(node, out, path, ctx);
  };
  spec.show = [](const T&) { return std::string(); };
  return spec;
}

/// Where a key of a map was written, for cross-key messages (the map itself if absent).
const Origin& origin_of(const Node& map, const std::string& key) {
  const Node* value = map.find(key);
  return value ? value->origin : map.origin;
}

// ---------------------------------------------------------------------------------------
// The schema. Ranges are in the display unit of each dimension (deg for angles).

ValueSpec<Selector> selector_map() {
  auto sphere = map<Selector>({
      field("center", vec3(Dimension::kLength), &Selector::center, "Centre, in organ space (after units and centring)."),
      field("radius", quantity(Dimension::kLength, open_closed(0, 1000)), &Selector::radius_m, "Radius.").required(),
  });
  auto box = map<Selector>({
      field("min", vec3(Dimension::kLength), &Selector::min, "Lowest corner, in organ space.").required(),
      field("max", vec3(Dimension::kLength), &Selector::max, "Highest corner, in organ space.").required(),
  }, [](const Node& node, Selector& s, const std::string& path, const Context&) {
    if ((s.min.array() > s.max.array()).any())
      fail(origin_of(node, "max"), join(path, "max"), "every coordinate of max must be >= that of min");
  });
  auto half_space = map<Selector>({
      field("point", vec3(Dimension::kLength), &Selector::point, "A point on the boundary plane."),
      field("normal", direction(), &Selector::normal, "Points into the selected side (normalised on reading).").required(),
  }, [](const Node&, Selector& s, const std::string&, const Context&) { s.normal.normalize(); });

  return map<Selector>({
      field<Selector, std::string>("part", name_text(), [](Selector& s) -> std::string& { s.kind = SelectorKind::kPart; return s.part; },
            "A named part: a procedural organ's anatomical part or a mesh file's sub-mesh.").shown_default("—"),
      field<Selector, Selector>("sphere", sphere, [](Selector& s) -> Selector& { s.kind = SelectorKind::kSphere; return s; },
            "Vertices within `radius` of `center`."),
      field<Selector, Selector>("box", box, [](Selector& s) -> Selector& { s.kind = SelectorKind::kBox; return s; },
            "Vertices inside the axis-aligned box."),
      field<Selector, Selector>("half_space", half_space, [](Selector& s) -> Selector& { s.kind = SelectorKind::kHalfSpace; return s; },
            "Vertices on the `normal` side of the plane through `point`."),
  }, [](const Node& node, Selector& s, const std::string& path, const Context&) {
    if (node.entries.size() != 1)
      fail(node.origin, path, "a selector has exactly one of part, sphere, box, half_space; got " +
                                  std::to_string(node.entries.size()) + " keys");
    s.origin = node.origin;
  });
}

/// `select`: "all", one selector map, or a list of them (their union).
ValueSpec<std::vector<Selector>> selection() {
  const ValueSpec<Selector> one = selector_map();
  ValueSpec<std::vector<Selector>> spec;
  spec.type = "selector or list";
  spec.range = "`all`, a selector map, or a list of these";
  spec.keys = one.keys;
  auto read_one = [one](const Node& node, const std::string& path, const Context& ctx) {
    Selector s;
    if (node.kind == Node::Kind::kScalar && node.scalar == "all") {
      s.origin = node.origin;
      return s;
    }
    if (node.kind != Node::Kind::kMap)
      fail(node.origin, path, "expected \"all\" or a selector map (part, sphere, box or half_space); got " + node.describe());
    one.read(node, s, path, ctx);
    return s;
  };
  spec.read = [read_one](const Node& node, std::vector<Selector>& out, const std::string& path, const Context& ctx) {
    out.clear();
    if (node.kind == Node::Kind::kList) {
      if (node.items.empty()) fail(node.origin, path, "expected at least one selector; got an empty list");
      for (std::size_t i = 0; i < node.items.size(); ++i)
        out.push_back(read_one(node.items[i], path + "[" + std::to_string(i) + "]", ctx));
    } else {
      out.push_back(read_one(node, path, ctx));
    }
  };
  spec.show = [](const std::vector<Selector>&) { return std::string("the part named like the region"); };
  return spec;
}

ValueSpec<Drive> drive_spec() {
  auto harmonic = map<Harmonic>({
      field("amplitude", number(closed(0, 0.5)), &Harmonic::amplitude, "Weight of this harmonic in phi."),
      field("phase", quantity(Dimension::kAngle, any()), &Harmonic::phase_rad, "Phase of this harmonic."),
  });
  auto rate = quantity(Dimension::kFrequency, closed(0, 20));
  return map<Drive>({
      field("waveform", choice<Waveform>({{"none", Waveform::kNone}, {"sine", Waveform::kSine}, {"fourier", Waveform::kFourier},
                                          {"cardiac", Waveform::kCardiac}, {"breathing", Waveform::kBreathing}, {"samples", Waveform::kSamples}}),
            &Drive::waveform, "Shape of phi(t) over one period; `none` leaves the region passive."),
      field("rate", rate, &Drive::rate_hz, "Cycles per unit time at the start of the clip (72 bpm = 1.2 Hz)."),
      field("rate_end", rate, &Drive::rate_end_hz, "When > 0, the rate ramps linearly to this by the clip's end."),
      field("amplitude", number(closed(0, 0.95)), &Drive::amplitude, "Fraction of rest length removed at phi = 1."),
      field("phase", quantity(Dimension::kAngle, any()), &Drive::phase_rad, "Phase offset of the cycle."),
      field("delay", quantity(Dimension::kTime, closed(0, 60)), &Drive::delay_s, "Activation delay (atria before ventricles)."),
      field("systolic_fraction", number(open(0.05, 0.95)), &Drive::systolic_fraction, "`cardiac`: part of the period spent contracting."),
      field("inhale_fraction", number(open(0.05, 0.95)), &Drive::inhale_fraction, "`breathing`: part of the period spent inhaling."),
      field("harmonics", list(harmonic, 0, 32, "list of harmonics"), &Drive::harmonics,
            "`fourier`: harmonic k = 1, 2, ... as {amplitude, phase}; amplitudes sum to at most 0.5."),
      field("samples", list(number(closed(0, 1)), 2, 1024, "list of numbers"), &Drive::samples,
            "`samples`: phi over one period, evenly spaced, interpolated periodically."),
      field("irregularity", number(closed(0, 0.5)), &Drive::irregularity, "Seeded beat-to-beat jitter of the period (0 = regular)."),
  }, [](const Node& node, Drive& d, const std::string& path, const Context&) {
    if (d.waveform == Waveform::kNone) return;
    if (d.rate_hz <= 0)
      fail(origin_of(node, "rate"), join(path, "rate"), "a driven region (waveform other than none) needs a rate > 0, e.g. \"72 bpm\"");
    if (d.waveform == Waveform::kFourier && d.harmonics.empty())
      fail(origin_of(node, "harmonics"), join(path, "harmonics"), "waveform fourier needs at least one harmonic");
    if (d.waveform == Waveform::kSamples && d.samples.empty())
      fail(origin_of(node, "samples"), join(path, "samples"), "waveform samples needs a list of 2..1024 samples");
    // phi = 1/2 + sum a_k cos(...) stays in [0, 1] only if the amplitudes sum to <= 1/2.
    double sum = 0;
    for (const Harmonic& h : d.harmonics) sum += h.amplitude;
    if (sum > 0.5 + 1e-12)
      fail(origin_of(node, "harmonics"), join(path, "harmonics"),
           "harmonic amplitudes sum to " + format_number(sum) + "; at most 0.5 keeps phi within [0, 1]");
  });
}

/// A list of {time, position} keys with increasing times.
ValueSpec<std::vector<PathKey>> path_keys(std::string position_doc) {
  auto key = map<PathKey>({
      field("time", quantity(Dimension::kTime, closed(0, 3600)), &PathKey::time_s, "When the point is here.").required(),
      field("position", vec3(Dimension::kLength), &PathKey::position_m, std::move(position_doc)).required(),
  });
  return list(key, 1, 1024, "list of path keys").also(
      [](const std::vector<PathKey>& keys) {
        for (std::size_t i = 1; i < keys.size(); ++i)
          if (keys[i].time_s <= keys[i - 1].time_s) return "times must increase (key " + std::to_string(i) + ")";
        return std::string();
      },
      "1..1024 keys, times increasing");
}

/// Two numbers [lo, hi] with lo < hi.
ValueSpec<Eigen::Vector2d> value_pair() {
  ValueSpec<Eigen::Vector2d> spec;
  spec.type = "2 numbers";
  spec.range = "[lo, hi], lo < hi";
  spec.read = [](const Node& node, Eigen::Vector2d& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kList || node.items.size() != 2)
      fail(node.origin, path, "expected a list of 2 numbers [lo, hi]; got " + node.describe());
    for (int i = 0; i < 2; ++i) out[i] = parse_quantity(node.items[i], Dimension::kNumber, path + "[" + std::to_string(i) + "]");
    if (!(out[0] < out[1])) fail(node.origin, path, "expected lo < hi; got [" + format_number(out[0]) + ", " + format_number(out[1]) + "]");
  };
  spec.show = [](const Eigen::Vector2d& v) { return "[" + format_number(v[0]) + ", " + format_number(v[1]) + "]"; };
  return spec;
}

ValueSpec<ClipPlane> clip_spec() {
  return map<ClipPlane>({
      field("point", vec3(Dimension::kLength), &ClipPlane::point_m, "A point on the cutting plane (world space)."),
      field("normal", direction(), &ClipPlane::normal, "Points to the side kept; the other side is cut away (normalised on reading).").required(),
      field("cut_color", color(), &ClipPlane::cut_color, "Flat colour of the inside seen through the cut (sRGB)."),
  }, [](const Node&, ClipPlane& c, const std::string&, const Context&) {
    c.enabled = true;
    c.normal.normalize();
  });
}

ValueSpec<Region> region_spec() {
  return map<Region>({
      field("name", name_text(), &Region::name, "Unique within the organ; also the default part to select.").required(),
      field("select", selection(), &Region::select, "Which vertices belong to the region (a list is a union); later regions take vertices from earlier ones."),
      field("drive", drive_spec(), &Region::drive, "The region's rhythm: L(t) = L0 (1 - amplitude phi(t - delay))."),
      field("stiffness", number(open_closed(0, 1e6)), &Region::stiffness_scale, "Multiplies the body's stiffness."),
      field("damping", number(closed(0, 1e6)), &Region::damping_scale, "Multiplies the body's damping."),
      field("pinned", boolean(), &Region::pinned, "Fixed in place (valves, vessel stumps)."),
      field("detail", choice<int>({{"1", 1}, {"2", 2}, {"4", 4}}), &Region::detail, "Reduced model (`body.lattice`) only: the region's voxels are split into detail^3, so it keeps more detail."),
      field("motion", path_keys("Offset of the region from its rest position."), &Region::motion,
            "Pinned regions: a prescribed motion (a kinematic region), smoothly interpolated, held after the last key."),
      field<Region, Color>("color", color(), [](Region& r) -> Color& { r.has_color = true; return r.color; },
            "Colour of the region; else the organ's material colour.").shown_default("material color"),
      field<Region, double>("opacity", number(closed(0, 1)), [](Region& r) -> double& { r.has_opacity = true; return r.opacity; },
            "Opacity of the region; else the material's.").shown_default("material opacity"),
  }, [](const Node& node, Region& r, const std::string& path, const Context&) {
    r.origin = node.origin;
    if (!r.motion.empty() && !r.pinned)
      fail(origin_of(node, "motion"), join(path, "motion"), "a prescribed motion needs pinned: true (the region is moved, not simulated)");
  });
}

ValueSpec<MeshSource> mesh_spec() {
  return map<MeshSource>({
      field("file", path_text(), &MeshSource::file, "Mesh file (OBJ, STL, PLY, glTF, ...), relative to the scene's folder."),
      field("procedural", name_text(), &MeshSource::procedural, "A generated organ, e.g. `heart`."),
      field("detail", whole<int>(1, 6), &MeshSource::detail, "`procedural` only: level of detail, 1 (coarse) to 6 (fine)."),
      field("units", choice<double>({{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}), &MeshSource::unit_m, "`file` only: the file's length unit."),
      field("center", boolean(), &MeshSource::center, "Move the mesh's bounding-box centre to the origin."),
  }, [](const Node& node, MeshSource& m, const std::string& path, const Context& ctx) {
    m.origin = node.origin;
    const bool has_file = node.find("file") != nullptr, has_procedural = node.find("procedural") != nullptr;
    if (has_file == has_procedural)
      fail(node.origin, path, std::string("expected exactly one of file, procedural; got ") + (has_file ? "both" : "neither"));
    if (has_file && node.find("detail")) fail(origin_of(node, "detail"), join(path, "detail"), "applies only to a procedural mesh");
    if (has_procedural && node.find("units")) fail(origin_of(node, "units"), join(path, "units"), "applies only to a mesh file");
    if (has_file) {
      const std::filesystem::path file = std::filesystem::path(m.file).is_absolute() ? std::filesystem::path(m.file) : ctx.base_dir / m.file;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(file, ec))
        throw Error(ExitCode::kNoInput, where(origin_of(node, "file")) + join(path, "file") + ": " +
                                            (std::filesystem::exists(file, ec) ? "not a regular file" : "mesh file not found") +
                                            ": " + file.lexically_normal().string());
      m.file = file.lexically_normal().string();
    }
  });
}

/// `target`: the motion `systole tune` fits the organ's regions to (train/).
ValueSpec<Target> target_spec() {
  auto frame = map<TargetFrame>({
      field("file", path_text(), &TargetFrame::file, "Mesh file with the organ's vertices in the same order, in the organ mesh's units and frame.").required(),
      field("time", quantity(Dimension::kTime, closed(0, 3600)), &TargetFrame::time_s, "Time of this key within the period.").required(),
  }, [](const Node& node, TargetFrame& f, const std::string& path, const Context& ctx) {
    const std::filesystem::path file = std::filesystem::path(f.file).is_absolute() ? std::filesystem::path(f.file) : ctx.base_dir / f.file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      throw Error(ExitCode::kNoInput, where(origin_of(node, "file")) + join(path, "file") + ": key-frame file not found: " + file.lexically_normal().string());
    f.file = file.lexically_normal().string();
  });
  auto samples = list(number(open_closed(0, 10)), 2, 1024, "list of numbers");
  auto curve = map<TargetCurve>({
      field("region", name_text(), &TargetCurve::region, "The region whose size the curve gives.").required(),
      field("scale", samples, &TargetCurve::samples, "Linear size relative to rest over one period, evenly spaced."),
      field<TargetCurve, std::vector<double>>("volume", samples, [](TargetCurve& c) -> std::vector<double>& { c.volume = true; return c.samples; },
            "Volume relative to rest over one period, evenly spaced (a ventricular volume curve)."),
  }, [](const Node& node, TargetCurve& c, const std::string& path, const Context&) {
    c.origin = node.origin;
    if ((node.find("scale") != nullptr) == (node.find("volume") != nullptr))
      fail(node.origin, path, "a curve has exactly one of scale, volume");
  });
  return map<Target>({
      field("rate", quantity(Dimension::kFrequency, open_closed(0, 20)), &Target::rate_hz, "Cycles per unit time of the target; the tuned drives run at it.").required(),
      field("frames", list(frame, 2, 4096, "list of key frames"), &Target::frames, "Key-frame meshes at times within one period, interpolated smoothly and periodically."),
      field("curves", list(curve, 1, 256, "list of curves"), &Target::curves, "Per-region size curves over one period (instead of frames)."),
      field("animation", path_text(), &Target::animation,
            "An animated mesh file (glTF/GLB, FBX, Collada...) of the organ's own mesh: its first animation (morph targets and/or skinning) is one period."),
      field("samples", whole<int>(4, 1024), &Target::animation_samples, "Poses sampled evenly from the animation over one period."),
      field("coupling", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Target::coupling_N_per_m, "Stiffness tying each particle to its target while the driving forces are recorded."),
      field("harmonics", whole<int>(1, 16), &Target::harmonics, "Fourier harmonics of each fitted drive."),
      field("lock", list(path_text(), 0, 1024, "list of names"), &Target::lock,
            "Parameters the tuner keeps as the scene writes them: `amplitude`, `shape`, `delay`, `stiffness` (all regions), a region's name (all its parameters), or `region.param`."),
      field("budget", whole<int>(0, 1000000), &Target::budget, "Playbacks the tuner may run (0: fit only)."),
      field("settle", number(closed(0, 100)), &Target::settle_cycles, "Cycles run before the error is measured."),
      field("measure", number(open_closed(0, 100)), &Target::measure_cycles, "Cycles over which the error is measured."),
  }, [](const Node& node, Target& t, const std::string& path, const Context& ctx) {
    t.enabled = true;
    t.origin = node.origin;
    if (int(!t.frames.empty()) + int(!t.curves.empty()) + int(!t.animation.empty()) != 1)
      fail(node.origin, path, "expected exactly one of frames, curves, animation");
    if (node.find("samples") != nullptr && t.animation.empty()) fail(origin_of(node, "samples"), join(path, "samples"), "applies to an animation only");
    if (!t.animation.empty()) {
      const std::filesystem::path file = std::filesystem::path(t.animation).is_absolute() ? std::filesystem::path(t.animation) : ctx.base_dir / t.animation;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(file, ec))
        throw Error(ExitCode::kNoInput, where(origin_of(node, "animation")) + join(path, "animation") + ": animation file not found: " + file.lexically_normal().string());
      t.animation = file.lexically_normal().string();
    }
    const double period_s = 1.0 / t.rate_hz;
    for (std::size_t i = 0; i < t.frames.size(); ++i) {
      const Origin& at = node.find("frames")->items[i].origin;
      if (i > 0 && t.frames[i].time_s <= t.frames[i - 1].time_s) fail(at, path + ".frames[" + std::to_string(i) + "].time", "times must increase");
      if (t.frames[i].time_s >= period_s)
        fail(at, path + ".frames[" + std::to_string(i) + "].time", "must lie within one period (" + format_quantity(period_s, Dimension::kTime) + " at this rate)");
    }
  });
}

/// The target's region names and lock entries must name the organ's regions.
void check_target_names(const Node& node, const Organ& o, const std::string& path) {
  if (!o.target.enabled) return;
  const Node& target = *node.find("target");
  auto region = [&](const std::string& name) {
    return std::find_if(o.regions.begin(), o.regions.end(), [&](const Region& r) { return r.name == name; });
  };
  for (std::size_t i = 0; i < o.target.curves.size(); ++i) {
    const TargetCurve& c = o.target.curves[i];
    const auto r = region(c.region);
    if (r == o.regions.end()) fail(c.origin, path + ".target.curves[" + std::to_string(i) + "].region", "the organ has no region '" + c.region + "'");
    if (r->pinned) fail(c.origin, path + ".target.curves[" + std::to_string(i) + "].region", "region '" + c.region + "' is pinned: it cannot follow a curve");
  }
  const std::vector<std::string> params = {"amplitude", "shape", "delay", "stiffness"};
  for (std::size_t i = 0; i < o.target.lock.size(); ++i) {
    const std::string& entry = o.target.lock[i];
    const std::size_t dot = entry.find('.');
    const std::string head = entry.substr(0, dot), param = dot == std::string::npos ? "" : entry.substr(dot + 1);
    const bool is_param = std::find(params.begin(), params.end(), head) != params.end() && dot == std::string::npos;
    const bool good = is_param || (region(head) != o.regions.end() &&
                                   (param.empty() || std::find(params.begin(), params.end(), param) != params.end()));
    if (!good)
      fail(target.find("lock")->items[i].origin, path + ".target.lock[" + std::to_string(i) + "]",
           "expected amplitude, shape, delay, stiffness, a region's name, or region.param with one of those; got '" + entry + "'");
  }
}

ValueSpec<Organ> organ_spec() {
  return map<Organ>({
      field("name", name_text(), &Organ::name, "Unique name; -D paths may use it (organs.heart.body.mass).").required(),
      field("mesh", mesh_spec(), &Organ::mesh, "Where the surface comes from: exactly one of `file` or `procedural`.").required(),
      field("transform", map<Transform>({
                field("translate", vec3(Dimension::kLength), &Transform::translate_m, "Position of the organ."),
                field("rotate", vec3(Dimension::kAngle), &Transform::rotate_rad, "Euler angles, applied X, then Y, then Z."),
                field("scale", number(open_closed(0, 1000)), &Transform::scale, "Uniform scale, applied before rotation."),
            }), &Organ::transform, "Placement in the world, applied after units and centring."),
      field("material", map<Material>({
                field("color", color(), &Material::color, "Surface colour (sRGB)."),
                field("specular", number(closed(0, 1)), &Material::specular, "Strength of the highlight."),
                field("shininess", number(closed(1, 1000)), &Material::shininess, "Blinn-Phong exponent: larger is a tighter highlight."),
                field("opacity", number(closed(0, 1)), &Material::opacity, "1 opaque; below 1 the organ is see-through (order-independent transparency, docs/teaching-visuals.md)."),
            }), &Organ::material, "How the surface looks."),
      field("color_by", choice<ColorBy>({{"material", ColorBy::kMaterial}, {"region", ColorBy::kRegion},
                                         {"strain", ColorBy::kStrain}, {"activation", ColorBy::kActivation}}),
            &Organ::color_by, "What the surface colour shows: `material` (region colours where set), `region` (every region a colour: its own or a palette's), `strain` (mean (L - L0) / L0 of each vertex's edges, blue shortened, red stretched), `activation` (the region's drive phi(t), dark to yellow)."),
      field<Organ, Eigen::Vector2d>("color_range", value_pair(), [](Organ& o) -> Eigen::Vector2d& { o.has_color_range = true; return o.color_range; },
            "`strain`, `activation`: the values at the two ends of the colour map.").shown_default("strain [-0.15, 0.15]; activation [0, 1]"),
      field("clip", clip_spec(), &Organ::clip, "Cuts the organ open along a plane.").shown_default("none"),
      field("body", map<Body>({
                field("mass", quantity(Dimension::kMass, open_closed(0, 1000)), &Body::mass_kg, "Total mass, spread over vertices by area."),
                field("stiffness", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Body::stiffness_N_per_m, "Spring stiffness of each surface edge."),
                field("damping", quantity(Dimension::kTime, closed(0, 1)), &Body::damping_s, "Stiffness-proportional damping time (c = k damping)."),
                field("volume_stiffness", quantity(Dimension::kPressure, closed(0, 1e9)), &Body::volume_stiffness_Pa, "Bulk modulus of the enclosed volume; 0 = no volume constraint."),
                field("drag", quantity(Dimension::kRate, closed(0, 1000)), &Body::drag_per_s, "Velocity damping towards rest (the surrounding tissue)."),
                field("bending", quantity(Dimension::kStiffness, closed(0, 1e9)), &Body::bending_N_per_m, "Stiffness of the springs across each edge, which resist folding; 0 = none."),
                field("lattice", whole<int>(0, 64), &Body::lattice, "Reduced model: voxels along the organ's longest side; their corners carry the motion and the mesh follows (docs/accuracy.md). 0 = full model, every vertex a particle."),
                field("volume_drive", drive_spec(), &Body::volume_drive, "Drives the rest volume instead of rest lengths: V0(t) = V0 (1 + amplitude phi(t - delay)), `amplitude` the fraction of volume added (lungs inflating). Needs `volume_stiffness` > 0 and a closed surface."),
            }), &Organ::body, "The soft body's physical parameters."),
      field("regions", list(region_spec(), 0, 256, "list of regions"), &Organ::regions, "Parts with their own rhythm and stiffness, applied in order."),
      field("target", target_spec(), &Organ::target, "Motion for `systole tune` to fit the regions' drives to (docs/training.md).").shown_default("none"),
  }, [](const Node& node, Organ& o, const std::string& path, const Context&) {
    o.origin = node.origin;
    check_target_names(node, o, path);
    if (!o.has_color_range) o.color_range = o.color_by == ColorBy::kActivation ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(-0.15, 0.15);
    for (std::size_t i = 0; i < o.regions.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (o.regions[i].name == o.regions[j].name)
          fail(origin_of(node.find("regions")->items[i], "name"), path + ".regions[" + std::to_string(i) + "].name",
               "duplicate region name '" + o.regions[i].name + "' (also regions[" + std::to_string(j) + "])");
  });
}

ValueSpec<Solver> solver_spec() {
  // dt is a time or the word "auto", and sets two members: a custom field.
  const Range dt_range = open_closed(0, 0.1);
  Field<Solver> dt{KeySpec{"dt", "time or `auto`", "1/240 s", dt_range.text("s") + ", or `auto`",
                           "Step size; `auto` lets the solver choose from the drive and stiffness.", {}},
                   false, [dt_range](const Node& node, Solver& s, const std::string& path, const Context&) {
                     if (node.kind == Node::Kind::kScalar && node.scalar == "auto") {
                       s.auto_dt = true;
                       return;
                     }
                     const double v = parse_quantity(node, Dimension::kTime, path);
                     check_range(node, v, Dimension::kTime, dt_range, path);
                     s.auto_dt = false;
                     s.dt_s = v;
                   }};
  return map<Solver>({
      field("method", choice<SolverMethod>({{"xpbd", SolverMethod::kXpbd}, {"explicit", SolverMethod::kExplicit}, {"implicit", SolverMethod::kImplicit}}),
            &Solver::method, "XPBD with substeps, explicit mass-spring (symplectic Euler), or implicit Euler."),
      dt,
      field("substeps", whole<int>(1, 200), &Solver::substeps, "XPBD substeps per step."),
      field("threads", whole<int>(1, 64), &Solver::threads, "Threads for the spring loops; frames are bit-identical at any count."),
  }, [](const Node& node, Solver& s, const std::string&, const Context&) { s.origin = node.origin; });
}

ValueSpec<Interaction> interaction_spec() {
  auto common = [](std::vector<Field<Interaction>> extra) {
    std::vector<Field<Interaction>> fields = {
        field("organ", name_text(), &Interaction::organ, "Name of the organ touched.").required(),
        field("at", vec3(Dimension::kLength), &Interaction::at_m, "Centre of the touched patch (world space, rest shape).").required(),
        field("radius", quantity(Dimension::kLength, open_closed(0, 1000)), &Interaction::radius_m, "Vertices within this distance of `at` are touched."),
    };
    fields.insert(fields.end(), extra.begin(), extra.end());
    return fields;
  };
  auto poke = map<Interaction>(common({
      field("force", vec3(Dimension::kForce), &Interaction::force_N, "Total force, shared by the patch's vertices.").required(),
      field("start", quantity(Dimension::kTime, closed(0, 3600)), &Interaction::start_s, "When the push starts."),
      field("duration", quantity(Dimension::kTime, open_closed(0, 3600)), &Interaction::duration_s, "How long the push lasts."),
      field("drive", drive_spec(), &Interaction::drive, "When given, the force is scaled by the drive's phi(t) all clip long instead (a periodic push: the diaphragm on the liver); start and duration are then unused."),
  }));
  auto grab = map<Interaction>(common({
      field("path", path_keys("Where the handle is."), &Interaction::path,
            "Handle positions at increasing times; the patch follows from the first key and is let go after the last.").required(),
      field("stiffness", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Interaction::stiffness_N_per_m, "Stiffness holding each vertex to the handle."),
  }));
  return map<Interaction>({
      field<Interaction, Interaction>("poke", poke, [](Interaction& i) -> Interaction& { i.kind = InteractionKind::kPoke; return i; },
            "Push the vertices near `at` with `force` from `start` for `duration`."),
      field<Interaction, Interaction>("grab", grab, [](Interaction& i) -> Interaction& { i.kind = InteractionKind::kGrab; return i; },
            "Drag the vertices near `at` along `path`, then let go."),
  }, [](const Node& node, Interaction& i, const std::string& path, const Context&) {
    if (node.entries.size() != 1)
      fail(node.origin, path, "an interaction has exactly one of poke, grab; got " + std::to_string(node.entries.size()) + " keys");
    i.origin = node.origin;
  });
}

ValueSpec<Floor> floor_spec() {
  return map<Floor>({
      field("point", vec3(Dimension::kLength), &Floor::point_m, "A point on the plane."),
      field("normal", direction(), &Floor::normal, "Points to the free side (normalised on reading)."),
  }, [](const Node&, Floor& f, const std::string&, const Context&) {
    f.enabled = true;
    f.normal.normalize();
  });
}

ValueSpec<Camera> camera_spec() {
  auto orbit = map<Orbit>({
      field("speed", quantity(Dimension::kAngularSpeed, closed(-3600, 3600)), &Orbit::speed_rad_per_s, "Turning speed; negative turns the other way."),
      field("axis", direction(), &Orbit::axis, "Axis through the target the eye turns about (normalised on reading)."),
  }, [](const Node&, Orbit& o, const std::string&, const Context&) {
    o.enabled = true;
    o.axis.normalize();
  });
  auto key = map<CameraKey>({
      field("time", quantity(Dimension::kTime, closed(0, 3600)), &CameraKey::time_s, "When the camera is here.").required(),
      field("position", vec3(Dimension::kLength), &CameraKey::position_m, "Eye position.").required(),
      field("target", vec3(Dimension::kLength), &CameraKey::target_m, "Point looked at.").required(),
  });
  auto path_spec = list(key, 1, 1024, "list of camera keys").also(
      [](const std::vector<CameraKey>& keys) {
        for (std::size_t i = 1; i < keys.size(); ++i)
          if (keys[i].time_s <= keys[i - 1].time_s) return "times must increase (key " + std::to_string(i) + ")";
        return std::string();
      },
      "1..1024 keys, times increasing");
  return map<Camera>({
      field("position", vec3(Dimension::kLength), &Camera::position_m, "Eye position."),
      field("target", vec3(Dimension::kLength), &Camera::target_m, "Point looked at."),
      field("up", direction(), &Camera::up, "Up direction (not parallel to the view)."),
      field("fov", quantity(Dimension::kAngle, open(1, 170)), &Camera::fov_rad, "Vertical field of view."),
      field("orbit", orbit, &Camera::orbit, "Turntable: the eye turns about `axis` through the target, starting at `position`.").shown_default("none"),
      field("path", path_spec, &Camera::path, "Key-framed camera: a Catmull-Rom curve through the keys' positions and targets, held before the first and after the last; `position` and `target` are then unused."),
  }, [](const Node& node, Camera& c, const std::string& path, const Context&) {
    if (c.orbit.enabled && !c.path.empty())
      fail(origin_of(node, "orbit"), join(path, "orbit"), "a camera has an orbit or a path, not both");
    const auto check_view = [&](const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const std::string& key) {
      const Eigen::Vector3d view = target - eye;
      if (view.norm() < 1e-9) fail(origin_of(node, key), join(path, key), "target must differ from position");
      if (view.normalized().cross(c.up.normalized()).norm() < 1e-6)
        fail(origin_of(node, "up"), join(path, "up"), "must not be parallel to the view direction (target - position)");
    };
    if (c.path.empty()) {
      check_view(c.position_m, c.target_m, "target");
    } else {
      for (const CameraKey& k : c.path) check_view(k.position_m, k.target_m, "path");
      c.position_m = c.path.front().position_m;
      c.target_m = c.path.front().target_m;
    }
  });
}

std::string format_name(Format f) {
  switch (f) {
    case Format::kMp4: return "mp4";
    case Format::kMkv: return "mkv";
    case Format::kWebm: return "webm";
    case Format::kGif: return "gif";
    default: return "auto";
  }
}

/// The format a file's extension names (any case); kAuto for none.
Format format_of_file(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (Format f : {Format::kMp4, Format::kMkv, Format::kWebm, Format::kGif})
    if (ext == "." + format_name(f)) return f;
  return Format::kAuto;
}

ValueSpec<Card> card_spec() {
  return map<Card>({
      field("text", screen_text(500, false), &Card::text, "The card's words; a line break (\\n, or a YAML block) starts a smaller line under the title.").required(),
      field("duration", quantity(Dimension::kTime, open_closed(0, 60)), &Card::duration_s, "How long the card shows (video time)."),
      field("fade", quantity(Dimension::kTime, closed(0, 10)), &Card::fade_s, "Fade in at the start and out at the end."),
      field("size", number(open_closed(0, 0.5)), &Card::size, "Title height as a fraction of the frame height."),
      field("color", color(), &Card::color, "Text colour (sRGB); the card is the background colour."),
  }, [](const Node& node, Card& c, const std::string& path, const Context&) {
    if (2 * c.fade_s > c.duration_s)
      fail(origin_of(node, "fade"), join(path, "fade"), "twice the fade (" + format_number(c.fade_s) + " s) must fit in the duration (" +
                                                        format_number(c.duration_s) + " s)");
    c.origin = node.origin;
  });
}

ValueSpec<Caption> caption_spec() {
  return map<Caption>({
      field("text", screen_text(500, false), &Caption::text, "The caption's words, one line.").required(),
      field("from", quantity(Dimension::kTime, closed(0, 36000)), &Caption::from_s, "Start, in video time from the clip's first frame (after the cards).").required(),
      field("to", quantity(Dimension::kTime, open_closed(0, 36000)), &Caption::to_s, "End, in video time (after from).").required(),
      field("fade", quantity(Dimension::kTime, closed(0, 10)), &Caption::fade_s, "Fade in after from and out before to."),
      field("size", number(open_closed(0, 0.5)), &Caption::size, "Text height as a fraction of the frame height."),
      field("color", color(), &Caption::color, "Text colour (sRGB), over a dark band."),
  }, [](const Node& node, Caption& c, const std::string& path, const Context&) {
    if (c.to_s <= c.from_s)
      fail(origin_of(node, "to"), join(path, "to"), format_number(c.to_s) + " s must be after from (" + format_number(c.from_s) + " s)");
    if (2 * c.fade_s > c.to_s - c.from_s)
      fail(origin_of(node, "fade"), join(path, "fade"), "twice the fade (" + format_number(c.fade_s) + " s) must fit between from and to (" +
                                                        format_number(c.to_s - c.from_s) + " s)");
    c.origin = node.origin;
  });
}

ValueSpec<View> view_spec() {
  return map<View>({
      field<View, Camera>("camera", camera_spec(), [](View& v) -> Camera& { v.has_camera = true; return v.camera; },
            "This view's camera.").shown_default("the scene's camera"),
      field("organs", list(name_text(), 1, 64, "list of names"), &View::organs, "Names of the organs shown.").shown_default("every organ"),
      field("clip", clip_spec(), &View::clip, "Cuts this view's organs that have no clip of their own.").shown_default("none"),
      field("title", screen_text(200, true), &View::title, "Caption of the view, drawn by the overlay."),
  }, [](const Node& node, View& v, const std::string&, const Context&) { v.origin = node.origin; });
}

ValueSpec<Output> output_spec() {
  auto even_size = whole<int>(16, 7680).also(
      [](const int& v) {
        return v % 2 == 0 ? std::string()
                          : std::to_string(v) + " is odd; H.264 with yuv420p needs even sizes; use " + std::to_string(v - 1) +
                                " or " + std::to_string(v + 1);
      },
      "16..7680, even");
  return map<Output>({
      field("file", path_text(), &Output::file, "Video path (relative to the working directory).").shown_default("out/<scene name>.<format>"),
      field("width", even_size, &Output::width, "Frame width in pixels."),
      field("height", even_size, &Output::height, "Frame height in pixels."),
      field("fps", number(open_closed(0, 240)), &Output::fps, "Frames per second of video."),
      field("format", choice<Format>({{"auto", Format::kAuto}, {"mp4", Format::kMp4}, {"mkv", Format::kMkv}, {"webm", Format::kWebm}, {"gif", Format::kGif}}),
            &Output::format, "Container and codec: mp4 (H.264), mkv (FFV1, lossless RGB), webm (VP9), gif (one palette, for slides); auto takes the video file's extension (.mp4, .mkv, .webm, .gif), else mp4."),
      field("duration", quantity(Dimension::kTime, open_closed(0, 3600)), &Output::duration_s, "Organ time the clip shows (the video lasts duration x slow_motion); with loop, rounded to whole cycles."),
      field("slow_motion", number(closed(0.1, 100)), &Output::slow_motion, "Video seconds per second of organ time: 4 plays a beat 4x slower (the body is still simulated at its true rate); below 1 speeds up."),
      field("loop", boolean(), &Output::loop, "Make a seamless loop: duration snaps to whole cycles of the slowest drive (and of every other), the clip starts after settle_cycles, and its last frame flows into its first."),
      field("settle_cycles", whole<int>(0, 100), &Output::settle_cycles, "loop: cycles of the slowest drive simulated (not shown) before the clip starts, at least; rounded up to whole loops."),
      field("quality", choice<Quality>({{"draft", Quality::kDraft}, {"standard", Quality::kStandard}, {"archival", Quality::kArchival}}),
            &Output::quality, "Encoder settings by purpose: draft (x264 ultrafast, CRF 23), standard (veryfast, CRF 20), archival (slow, CRF 16). crf and preset override them."),
      field("crf", whole<int>(0, 51), &Output::crf, "x264 constant rate factor: 0 lossless (High 4:4:4 Predictive profile, which some browsers do not play), 51 worst.").shown_default("by quality"),
      field("preset", choice<std::string>({{"ultrafast", "ultrafast"}, {"superfast", "superfast"}, {"veryfast", "veryfast"},
                                           {"faster", "faster"}, {"fast", "fast"}, {"medium", "medium"}, {"slow", "slow"},
                                           {"slower", "slower"}, {"veryslow", "veryslow"}, {"placebo", "placebo"}}),
            &Output::preset, "x264 speed/size preset.").shown_default("by quality"),
      // 0, 2 and 4 are the sample counts this key took before FXAA existed.
      field("antialias", choice<Antialias>({{"off", Antialias::kOff}, {"fxaa", Antialias::kFxaa}, {"msaa2", Antialias::kMsaa2},
                                            {"msaa4", Antialias::kMsaa4}, {"0", Antialias::kOff}, {"2", Antialias::kMsaa2},
                                            {"4", Antialias::kMsaa4}}),
            &Output::antialias, "Edge smoothing: fxaa (a post pass, cheap), msaa2 or msaa4 (2 or 4 samples per pixel, slower), off; 0, 2, 4 mean off, msaa2, msaa4."),
      field("background", color(), &Output::background, "Background colour (sRGB)."),
  }, [](const Node& node, Output& o, const std::string& path, const Context&) {
    // The quality names a preset and CRF (measured: docs/performance.md); keys written out win.
    const auto [crf, preset] = o.quality == Quality::kDraft      ? std::pair{23, "ultrafast"}
                               : o.quality == Quality::kArchival ? std::pair{16, "slow"}
                                                                 : std::pair{20, "veryfast"};
    if (!node.find("crf")) o.crf = crf;
    if (!node.find("preset")) o.preset = preset;
    const Format named = format_of_file(o.file);
    if (o.format != Format::kAuto && named != Format::kAuto && named != o.format)
      fail(origin_of(node, "format"), join(path, "format"), "'" + format_name(o.format) + "' contradicts the file '" + o.file +
                                                                 "' (its extension names " + format_name(named) + "); drop one");
    if (o.format == Format::kAuto) o.format = named == Format::kAuto ? Format::kMp4 : named;
    if (o.format == Format::kGif && o.fps > 50)
      fail(origin_of(node, "fps"), join(path, "fps"), format_number(o.fps) + " is outside (0, 50] for a GIF: its delays are whole "
                                                      "centiseconds and browsers slow faster GIFs to 10 fps; use 25 or 50");
  });
}

/// A warm key light from the upper left and a cool, dimmer fill from the right, so the
/// organ reads as a solid even when a scene names no lights.
std::vector<Light> default_lights() {
  Light key;
  key.direction = Eigen::Vector3d(-0.4, -0.6, -1.0);
  key.color = Color(1.0, 0.96, 0.9);
  key.intensity = 1.0;
  Light fill;
  fill.direction = Eigen::Vector3d(0.7, 0.2, -0.7);
  fill.color = Color(0.8, 0.87, 1.0);
  fill.intensity = 0.35;
  return {key, fill};
}

/// A periodic drive of the scene, with where it was written, for resolve_loop.
struct Rhythm {
  const Drive* drive;
  std::string path;
  Origin origin;
};

/// output.loop: duration becomes the shortest whole number of cycles of the slowest drive
/// in which every other drive also completes whole cycles (within 0.1% of a cycle), times
/// round(duration / that); start_frame skips settle_cycles of the slowest drive, rounded up to
/// whole loops, so the clip starts at the same phase as t = 0.
void resolve_loop(const Node& node, Scene& s) {
  Output& o = s.output;
  const Node* output_node = node.find("output");
  const Origin& where = output_node ? origin_of(*output_node, "loop") : node.origin;
  std::vector<Rhythm> rhythms;
  for (std::size_t i = 0; i < s.organs.size(); ++i) {
    const Organ& organ = s.organs[i];
    const std::string at = "organs[" + std::to_string(i) + "]";
    if (organ.body.volume_drive.waveform != Waveform::kNone)
      rhythms.push_back({&organ.body.volume_drive, at + ".body.volume_drive", organ.origin});
    for (std::size_t r = 0; r < organ.regions.size(); ++r) {
      const Region& region = organ.regions[r];
      const std::string region_at = at + ".regions[" + std::to_string(r) + "]";
      if (!region.motion.empty())
        fail(region.origin, region_at + ".motion", "a prescribed motion is held after its last key, so output.loop cannot repeat it; drop the loop or the motion");
      if (region.drive.waveform != Waveform::kNone && !region.pinned) rhythms.push_back({&region.drive, region_at + ".drive", region.origin});
    }
  }
  for (std::size_t i = 0; i < s.interactions.size(); ++i) {
    const Interaction& in = s.interactions[i];
    const std::string at = "interactions[" + std::to_string(i) + "]";
    if (in.kind == InteractionKind::kPoke && in.drive.waveform != Waveform::kNone) {
      rhythms.push_back({&in.drive, at + ".poke.drive", in.origin});
    } else {
      fail(in.origin, at, "happens once, so output.loop cannot repeat it seamlessly; drop the loop or give the poke a drive");
    }
  }
  if (rhythms.empty()) fail(where, "output.loop", "no region is driven, so there is no cycle to loop on");
  const Rhythm* slowest = &rhythms[0];
  for (const Rhythm& r : rhythms) {
    if (r.drive->rate_end_hz > 0)
      fail(r.origin, r.path + ".rate_end", "a ramping rate never repeats, so output.loop cannot close; drop rate_end or the loop");
    if (r.drive->irregularity > 0)
      fail(r.origin, r.path + ".irregularity", "an irregular rhythm never repeats, so output.loop cannot close; set it to 0 or drop the loop");
    if (r.drive->rate_hz < slowest->drive->rate_hz) slowest = &r;
  }
  if (!(slowest->drive->rate_hz > 0)) fail(slowest->origin, slowest->path + ".rate", "a loop needs a rate above 0");
  const double period = 1.0 / slowest->drive->rate_hz;
  int cycles = 0;  // Of the slowest drive, in which every drive completes whole cycles.
  for (int n = 1; n <= 64 && cycles == 0; ++n) {
    const bool whole = std::all_of(rhythms.begin(), rhythms.end(), [&](const Rhythm& r) {
      const double c = r.drive->rate_hz * n * period;
      return std::abs(c - std::round(c)) < 1e-3;
    });
    if (whole) cycles = n;
  }
  if (cycles == 0)
    fail(where, "output.loop", "the drives have no common cycle within 64 cycles of the slowest (" + slowest->path + " at " +
                                   format_quantity(slowest->drive->rate_hz, Dimension::kFrequency) + "); give them rates in whole-number ratios");
  const double common = cycles * period;
  const int repeats = std::max(1, static_cast<int>(std::lround(o.duration_s / common)));
  o.duration_s = repeats * common;
  if (o.frame_count() < 2)
    fail(where, "output.loop", "the loop (" + format_number(o.duration_s) + " s) is shorter than two frames; raise output.fps");
  const int loops_to_settle = static_cast<int>(std::ceil(o.settle_cycles * period / o.duration_s - 1e-9));
  o.start_frame = loops_to_settle * o.frame_count();
}

/// Text shown on screen (a title): any UTF-8 without control characters.
ValueSpec<std::string> display_text() {
  ValueSpec<std::string> spec;
  spec.type = "text";
  spec.range = "1..120 characters";
  spec.read = [](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path, "expected text such as \"Sinus rhythm\"; got " + node.describe());
    const std::string& s = node.scalar;
    if (s.size() > 120) fail(node.origin, path, "text of " + std::to_string(s.size()) + " bytes is longer than 120");
    if (std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
      fail(node.origin, path, "text must not contain control characters (tabs, line breaks)");
    out = s;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("none") : v; };
  return spec;
}

ValueSpec<Corner> corner() {
  return choice<Corner>({{"top-left", Corner::kTopLeft}, {"top-right", Corner::kTopRight},
                         {"bottom-left", Corner::kBottomLeft}, {"bottom-right", Corner::kBottomRight}});
}

/// `regions` of labels: "all" or a list of region names.
ValueSpec<std::vector<std::string>> region_names() {
  const ValueSpec<std::string> name = name_text();
  ValueSpec<std::vector<std::string>> spec;
  spec.type = "`all` or list of names";
  spec.range = "`all`, or 1..256 region names";
  spec.read = [name](const Node& node, std::vector<std::string>& out, const std::string& path, const Context& ctx) {
    out.clear();
    if (node.kind == Node::Kind::kScalar && node.scalar == "all") return;
    if (node.kind != Node::Kind::kList || node.items.empty() || node.items.size() > 256)
      fail(node.origin, path, "expected all or a list of region names, e.g. [left_ventricle, aorta]; got " + node.describe());
    for (std::size_t i = 0; i < node.items.size(); ++i) {
      std::string n;
      name.read(node.items[i], n, path + "[" + std::to_string(i) + "]", ctx);
      out.push_back(n);
    }
  };
  spec.show = [](const std::vector<std::string>& v) { return v.empty() ? std::string("all") : std::string("—"); };
  return spec;
}

ValueSpec<Overlay> overlay_spec() {
  const auto size = whole<int>(6, 96);
  auto labels = map<LabelsOverlay>({
      field("organ", name_text(), &LabelsOverlay::organ, "The organ whose regions are labelled.").shown_default("every organ"),
      field("regions", region_names(), &LabelsOverlay::regions, "The regions labelled."),
      field("size", size, &LabelsOverlay::size_px, "Text height in pixels of a 720-line frame (scaled with output.height)."),
  }, [](const Node& node, LabelsOverlay& l, const std::string&, const Context&) {
    l.enabled = true;
    l.origin = node.origin;
  });
  auto legend = map<LegendOverlay>({
      field("organ", name_text(), &LegendOverlay::organ, "The organ whose region colours are listed.").shown_default("the first organ"),
      field("position", corner(), &LegendOverlay::position, "Corner of the frame."),
      field("size", size, &LegendOverlay::size_px, "Text height in pixels of a 720-line frame."),
  }, [](const Node& node, LegendOverlay& l, const std::string&, const Context&) {
    l.enabled = true;
    l.origin = node.origin;
  });
  // window is a time or the word "clip" (0 inside).
  const Range window_range = open_closed(0, 600);
  Field<TraceOverlay> window{KeySpec{"window", "time or `clip`", "3 s", window_range.text("s") + ", or `clip`",
                                     "Width of the sweep (the cursor runs across it, then starts over); `clip`: the whole clip at once.", {}},
                             false, [window_range](const Node& node, TraceOverlay& t, const std::string& path, const Context&) {
                               if (node.kind == Node::Kind::kScalar && node.scalar == "clip") {
                                 t.window_s = 0;
                                 return;
                               }
                               const double v = parse_quantity(node, Dimension::kTime, path);
                               check_range(node, v, Dimension::kTime, window_range, path);
                               t.window_s = v;
                             }};
  auto trace = map<TraceOverlay>({
      field("signal", choice<TraceSignal>({{"volume", TraceSignal::kVolume}, {"activation", TraceSignal::kActivation}, {"ecg", TraceSignal::kEcg}}),
            &TraceOverlay::signal, "`volume`: the organ's enclosed volume as simulated; `activation`: a region's drive phi(t); `ecg`: a synthetic P-QRS-T at each beat of a region's drive.").required(),
      field("organ", name_text(), &TraceOverlay::organ, "The organ traced.").shown_default("the first organ"),
      field("region", name_text(), &TraceOverlay::region, "`activation`, `ecg`: the driven region whose beats are shown (`ecg`: a QRS-T at each beat: the ventricles)."),
      field("atria", name_text(), &TraceOverlay::atria, "`ecg`: the atrial region whose beats give the P waves; faster than 4 Hz (flutter, fibrillation): no P waves but f-waves following its drive. Default: a P wave 160 ms before each R."),
      field("position", corner(), &TraceOverlay::position, "Corner of the frame; insets in the same corner stack."),
      field("width", whole<int>(60, 1920), &TraceOverlay::width_px, "Inset width in pixels of a 720-line frame."),
      field("height", whole<int>(30, 1080), &TraceOverlay::height_px, "Inset height in pixels of a 720-line frame."),
      window,
  }, [](const Node& node, TraceOverlay& t, const std::string& path, const Context&) {
    t.origin = node.origin;
    const bool needs_region = t.signal != TraceSignal::kVolume;
    if (needs_region && t.region.empty())
      fail(node.origin, path, "signal activation and ecg need a region: the driven region whose beats are shown");
    if (t.signal != TraceSignal::kEcg && !t.atria.empty())
      fail(origin_of(node, "atria"), join(path, "atria"), "atria applies to signal ecg only");
    if (!needs_region && !t.region.empty())
      fail(origin_of(node, "region"), join(path, "region"), "signal volume is the whole organ's; region applies to activation and ecg");
  });
  return map<Overlay>({
      field("title", display_text(), &Overlay::title, "A title across the top of the frame."),
      field("title_size", size, &Overlay::title_size_px, "Title text height in pixels of a 720-line frame."),
      field("labels", labels, &Overlay::labels, "Region names beside their regions, with leader lines, following them as they move.").shown_default("none"),
      field("legend", legend, &Overlay::legend, "A key of the organ's region colours.").shown_default("none"),
      field("traces", list(trace, 0, 8, "list of traces"), &Overlay::traces, "Live plots of a signal over time with a moving cursor."),
  });
}

/// Cross-checks of the overlay against the organs: every name it uses exists, and traced
/// regions are driven.
void check_overlay(const Node& root, const Scene& s) {
  const Node* node = root.find("overlay");
  if (!node) return;
  auto find_organ = [&](const std::string& name, const Origin& origin, const std::string& path) -> const Organ* {
    if (name.empty()) return &s.organs.front();
    for (const Organ& o : s.organs)
      if (o.name == name) return &o;
    fail(origin, path, "no organ is named '" + name + "'");
    return nullptr;
  };
  auto find_region = [](const Organ& o, const std::string& name) -> const Region* {
    for (const Region& r : o.regions)
      if (r.name == name) return &r;
    return nullptr;
  };
  const Overlay& ov = s.overlay;
  if (ov.labels.enabled) {
    const Node* labels = node->find("labels");
    if (!ov.labels.organ.empty()) find_organ(ov.labels.organ, origin_of(*labels, "organ"), "overlay.labels.organ");
    for (std::size_t i = 0; i < ov.labels.regions.size(); ++i) {
      const std::string& name = ov.labels.regions[i];
      const bool found = std::any_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) {
        return (ov.labels.organ.empty() || o.name == ov.labels.organ) && find_region(o, name);
      });
      if (!found)
        fail(labels->find("regions")->items[i].origin, "overlay.labels.regions[" + std::to_string(i) + "]",
             "no region is named '" + name + "'" + (ov.labels.organ.empty() ? "" : " in organ '" + ov.labels.organ + "'"));
    }
  }
  if (ov.legend.enabled) find_organ(ov.legend.organ, origin_of(*node->find("legend"), "organ"), "overlay.legend.organ");
  for (std::size_t i = 0; i < ov.traces.size(); ++i) {
    const TraceOverlay& t = ov.traces[i];
    const std::string path = "overlay.traces[" + std::to_string(i) + "]";
    const Node& item = node->find("traces")->items[i];
    const Organ* organ = find_organ(t.organ, origin_of(item, "organ"), path + ".organ");
    if (t.signal == TraceSignal::kVolume) continue;
    const Region* r = find_region(*organ, t.region);
    if (!r) fail(origin_of(item, "region"), path + ".region", "organ '" + organ->name + "' has no region named '" + t.region + "'");
    if (r->drive.waveform == Waveform::kNone)
      fail(origin_of(item, "region"), path + ".region", "region '" + t.region + "' has no drive: nothing beats to trace");
    if (t.atria.empty()) continue;
    const Region* a = find_region(*organ, t.atria);
    if (!a) fail(origin_of(item, "atria"), path + ".atria", "organ '" + organ->name + "' has no region named '" + t.atria + "'");
    if (a->drive.waveform == Waveform::kNone)
      fail(origin_of(item, "atria"), path + ".atria", "region '" + t.atria + "' has no drive: it gives no P waves");
  }
}

ValueSpec<Scene> scene_spec() {
  auto light = map<Light>({
      field("direction", direction(), &Light::direction, "Direction the light travels."),
      field("color", color(), &Light::color, "Light colour (sRGB)."),
      field("intensity", number(closed(0, 100)), &Light::intensity, "Brightness multiplier."),
  });
  return map<Scene>({
      field("seed", whole<std::uint64_t>(0, std::numeric_limits<std::int64_t>::max()), &Scene::seed, "Seeds every random choice (irregular rhythms, tuning)."),
      field("gravity", vec3(Dimension::kAcceleration), &Scene::gravity, "Gravity acceleration."),
      field("organs", list(organ_spec(), 1, 64, "list of organs"), &Scene::organs, "The soft bodies in the scene.").required(),
      field("interactions", list(interaction_spec(), 0, 256, "list of interactions"), &Scene::interactions, "Scripted pokes and grabs on the timeline."),
      field("floor", floor_spec(), &Scene::floor, "A plane the organs cannot pass through.").shown_default("none"),
      field("solver", solver_spec(), &Scene::solver, "Time integration."),
      field("camera", camera_spec(), &Scene::camera, "The view."),
      field("lights", list(light, 1, 8, "list of lights"), &Scene::lights, "Directional lights.").shown_default("a warm key and a cool fill"),
      field("views", list(view_spec(), 0, 16, "list of views"), &Scene::views, "Split screen: panels side by side (up to 3) or in a grid, each with its own camera, organs and cut.").shown_default("one view of every organ"),
      field("output", output_spec(), &Scene::output, "The video file."),
      field("cards", list(card_spec(), 0, 16, "list of cards"), &Scene::cards, "Title cards shown in order before the clip: text on the background colour, fading in and out."),
      field("captions", list(caption_spec(), 0, 256, "list of captions"), &Scene::captions, "Text at the bottom of the clip over a time range, fading in and out."),
      field("overlay", overlay_spec(), &Scene::overlay, "Teaching overlays drawn on each frame: title, region labels, legend, trace insets (docs/teaching-visuals.md)."),
  }, [](const Node& node, Scene& s, const std::string&, const Context&) {
    if (!node.find("lights")) s.lights = default_lights();
    if (s.output.loop) resolve_loop(node, s);
    for (std::size_t i = 0; i < s.interactions.size(); ++i) {
      const auto& name = s.interactions[i].organ;
      if (std::none_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) { return o.name == name; }))
        fail(s.interactions[i].origin, "interactions[" + std::to_string(i) + "]", "no organ is named '" + name + "'");
    }
    for (std::size_t i = 0; i < s.views.size(); ++i)
      for (std::size_t k = 0; k < s.views[i].organs.size(); ++k) {
        const auto& name = s.views[i].organs[k];
        if (std::none_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) { return o.name == name; }))
          fail(node.find("views")->items[i].find("organs")->items[k].origin,
               "views[" + std::to_string(i) + "].organs[" + std::to_string(k) + "]", "no organ is named '" + name + "'");
      }
    for (std::size_t i = 0; i < s.organs.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (s.organs[i].name == s.organs[j].name)
          fail(origin_of(node.find("organs")->items[i], "name"), "organs[" + std::to_string(i) + "].name",
               "duplicate organ name '" + s.organs[i].name + "' (also organs[" + std::to_string(j) + "])");
    check_overlay(node, s);
  });
}

const ValueSpec<Scene>& the_scene_spec() {
  static const ValueSpec<Scene> spec = scene_spec();
  return spec;
}

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

const KeySpec* KeySpec::find(const std::string& key) const {
  for (const KeySpec& k : keys)
    if (k.name == key) return &k;
  return nullptr;
}

std::vector<std::string> KeySpec::key_names() const {
  std::vector<std::string> names;
  for (const KeySpec& k : keys) names.push_back(k.name);
  return names;
}

const KeySpec& scene_schema() {
  static const KeySpec root{"", "map", "", "", "A scene.", the_scene_spec().keys};
  return root;
}

Scene read_scene(const Node& root, const std::filesystem::path& base_dir) {
  Scene scene;
  the_scene_spec().read(root, scene, "", Context{base_dir});
  return scene;
}

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
