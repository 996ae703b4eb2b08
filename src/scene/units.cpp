#include "scene/units.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

namespace systole::scene {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// YAML's .nan/.inf and C's nan/inf: caught by name so the message can say "finite".
bool names_non_finite(std::string_view text) {
  std::string t = lower(trim(text));
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.erase(0, 1);
  if (!t.empty() && t[0] == '.') t.erase(0, 1);
  return t.starts_with("nan") || t.starts_with("inf");
}

// Parses a number at the start of `text` ("-1.5e3", "+2", ".5") and removes it.
std::optional<double> take_number(std::string_view& text) {
  std::string_view s = text;
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);  // from_chars refuses a leading '+'
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec == std::errc::invalid_argument) return std::nullopt;
  if (ec == std::errc::result_out_of_range) value = HUGE_VAL;  // reported as not finite
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return value;
}

const std::array<DimensionInfo, 14> kDimensions = {{
    {"number", {}, false, R"("0.5")"},
    {"length", {{"m", 1}, {"cm", 0.01}, {"mm", 0.001}}, false, R"("2 cm" or "0.02 m")"},
    {"mass", {{"kg", 1}, {"g", 0.001}}, false, R"("300 g" or "0.3 kg")"},
    {"time", {{"s", 1}, {"ms", 0.001}}, true, R"("10 s", "160 ms" or "1/240 s")"},
    {"frequency", {{"Hz", 1}, {"bpm", 1.0 / 60}, {"/min", 1.0 / 60}}, true, R"("72 bpm" or "1.2 Hz")"},
    {"angle", {{"deg", std::numbers::pi / 180}, {"rad", 1}}, true, R"("30 deg" or "0.5 rad")"},
    {"stiffness", {{"N/m", 1}}, false, R"("400 N/m")"},
    {"pressure", {{"Pa", 1}, {"kPa", 1000}, {"mmHg", 133.322}}, false, R"("20 kPa", "20000 Pa" or "35 mmHg")"},
    {"rate", {{"1/s", 1}}, false, R"("1 1/s")"},
    {"acceleration", {{"m/s^2", 1}}, false, R"("-9.81 m/s^2")"},
    {"force", {{"N", 1}}, false, R"("2 N")"},
    {"angular speed", {{"deg/s", std::numbers::pi / 180}, {"rad/s", 1}, {"rpm", 2 * std::numbers::pi / 60}}, true,
     R"("20 deg/s" or "3 rpm")"},
    {"level", {{"dB", 1}}, true, R"("-6 dB")"},
    {"elastance", {{"Pa/ml", 1e6}, {"kPa/ml", 1e9}, {"mmHg/ml", 133.322e6}}, true, R"("60 Pa/ml" or "0.45 mmHg/ml")"},
}};

std::string expectation(const DimensionInfo& d) {
  if (d.units.empty()) return "expected a number";
  return std::string("expected a") + (d.name == "acceleration" || d.name == "angular speed" ? "n " : " ") + std::string(d.name) +
         (d.unit_required ? " with a unit" : "") + ", e.g. " + std::string(d.example);
}

}  // namespace

const DimensionInfo& dimension_info(Dimension dimension) {
  return kDimensions[static_cast<std::size_t>(dimension)];
}

double parse_quantity(const Node& node, Dimension dimension, const std::string& path) {
  const DimensionInfo& info = dimension_info(dimension);
  if (node.kind != Node::Kind::kScalar) fail(node.origin, path, expectation(info) + "; got " + node.describe());
  if (names_non_finite(node.scalar)) fail(node.origin, path, "expected a finite number; got " + node.describe());

  std::string_view rest = trim(node.scalar);
  std::optional<double> value = take_number(rest);
  if (!value) fail(node.origin, path, expectation(info) + "; got " + node.describe());
  // "1/240 s": a fraction, told apart from the unit "/min" by the digit after the slash.
  if (rest.size() >= 2 && rest[0] == '/' && (std::isdigit(static_cast<unsigned char>(rest[1])) || rest[1] == '.')) {
    rest.remove_prefix(1);
    const std::optional<double> denominator = take_number(rest);
    if (!denominator || *denominator == 0)
      fail(node.origin, path, "expected a fraction with a non-zero denominator; got " + node.describe());
    *value /= *denominator;
  }
  if (!std::isfinite(*value)) fail(node.origin, path, "expected a finite number; got " + node.describe());

  const std::string unit = lower(trim(rest));
  if (unit.empty()) {
    if (info.unit_required && *value != 0) fail(node.origin, path, expectation(info) + "; got " + node.describe());
    return *value;  // a bare number is in SI units (or is 0 where a unit is required)
  }
  for (const Unit& u : info.units)
    if (lower(u.symbol) == unit) return *value * u.to_si;

  if (info.units.empty()) fail(node.origin, path, "expected a plain number without a unit; got " + node.describe());
  std::string allowed;
  for (const Unit& u : info.units) allowed += (allowed.empty() ? "" : ", ") + std::string(u.symbol);
  fail(node.origin, path,
       "unknown unit '" + std::string(trim(rest)) + "' in " + node.describe() + "; a " + std::string(info.name) +
           " takes " + allowed);
}

std::int64_t parse_integer(const Node& node, const std::string& path) {
  if (node.kind != Node::Kind::kScalar) fail(node.origin, path, "expected a whole number; got " + node.describe());
  std::string_view text = trim(node.scalar);
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) fail(node.origin, path, "whole number " + node.describe() + " is too large");
  if (ec != std::errc() || end != text.data() + text.size())
    fail(node.origin, path, "expected a whole number; got " + node.describe());
  return value;
}

std::string format_number(double value) {
  char buffer[64];
  // Ten digits keep user values exact in messages; past a million, 1e9 reads better than 1000000000.
  std::snprintf(buffer, sizeof buffer, std::fabs(value) >= 1e6 ? "%.6g" : "%.10g", value);
  std::string text = buffer;
  // "1e+09" -> "1e9", "1e-05" -> "1e-5": easier to read in docs and messages.
  const std::size_t e = text.find('e');
  if (e != std::string::npos) {
    std::string mantissa = text.substr(0, e);
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, 1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return text;
}

std::string format_quantity(double value_si, Dimension dimension) {
  const DimensionInfo& info = dimension_info(dimension);
  if (info.units.empty()) return format_number(value_si);
  return format_number(value_si / info.units[0].to_si) + " " + std::string(info.units[0].symbol);
}

}  // namespace systole::scene
