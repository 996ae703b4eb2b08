#pragma once
// Numbers with units, as scenes write them: "72 bpm", "1/240 s", "300 g", "30 deg".
// Everything is converted to SI on reading (scene.h stores SI only).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/tree.h"

namespace systole::scene {

/// What a number measures; decides which units it accepts and whether one is required.
enum class Dimension {
  kNumber,        ///< A plain number: no unit allowed.
  kLength,        ///< m, cm, mm; a bare number is metres.
  kMass,          ///< kg, g; a bare number is kilograms.
  kTime,          ///< s, ms; unit required (except 0).
  kFrequency,     ///< Hz, bpm, /min; unit required (except 0).
  kAngle,         ///< deg, rad; unit required (except 0).
  kStiffness,     ///< N/m; a bare number is N/m.
  kPressure,      ///< Pa, kPa; a bare number is Pa.
  kRate,          ///< 1/s; a bare number is 1/s.
  kAcceleration,  ///< m/s^2; a bare number is m/s^2.
  kForce,         ///< N; a bare number is newtons.
  kAngularSpeed,  ///< deg/s, rad/s, rpm; unit required (except 0).
  kLevel,         ///< dB (a loudness ratio, kept in dB: not converted); unit required (except 0).
  kElastance,     ///< Pa/ml, kPa/ml, mmHg/ml (pressure per volume); unit required (except 0).
};

struct Unit {
  std::string_view symbol;
  double to_si;  ///< Multiply by this to get SI.
};

struct DimensionInfo {
  std::string_view name;     ///< "frequency": for messages and docs.
  std::vector<Unit> units;   ///< The first is the display unit of messages and docs (may be non-SI: deg).
  bool unit_required;        ///< A bare non-zero number is rejected: "72" could be bpm or Hz.
  std::string_view example;  ///< R"("72 bpm" or "1.2 Hz")"
};

const DimensionInfo& dimension_info(Dimension dimension);

/// Reads a scalar "number [unit]" of `dimension`, returning SI. Fractions "1/240 s" are
/// accepted. Rejects NaN/Inf, a missing required unit and an unknown unit, naming `path`.
double parse_quantity(const Node& node, Dimension dimension, const std::string& path);

/// Reads a whole number (no fraction, no unit).
std::int64_t parse_integer(const Node& node, const std::string& path);

/// Shortest readable form for messages and docs: 0.35, 1e9, 0.004166666667.
std::string format_number(double value);

/// `value_si` in the dimension's display unit: "0.3 kg", "40 deg", "0.95".
std::string format_quantity(double value_si, Dimension dimension);

}  // namespace systole::scene
