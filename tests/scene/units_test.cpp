// scene/units.h: numbers with units read into SI, and numbers formatted back for messages.

#include "scene/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/error.h"

namespace systole::scene {
namespace {

/// Whether `text` contains `part` (gtest without gmock has no HasSubstr).
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

Node scalar(const std::string& text) {
  Node node;
  node.kind = Node::Kind::kScalar;
  node.scalar = text;
  node.origin = Origin{"units.yaml", 3, 7};
  return node;
}

double read(const std::string& text, Dimension d) { return parse_quantity(scalar(text), d, "organs[0].body.x"); }

/// The message parse_quantity throws for `text`, or "" when it reads.
std::string refusal(const std::string& text, Dimension d) {
  try {
    read(text, d);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    return e.what();
  }
  return "";
}

TEST(Units, ConvertsEveryUnitToSi) {
  EXPECT_DOUBLE_EQ(read("2 cm", Dimension::kLength), 0.02);
  EXPECT_DOUBLE_EQ(read("5 mm", Dimension::kLength), 0.005);
  EXPECT_DOUBLE_EQ(read("300 g", Dimension::kMass), 0.3);
  EXPECT_DOUBLE_EQ(read("160 ms", Dimension::kTime), 0.16);
  EXPECT_DOUBLE_EQ(read("72 bpm", Dimension::kFrequency), 1.2);
  EXPECT_DOUBLE_EQ(read("12 /min", Dimension::kFrequency), 0.2);
  EXPECT_DOUBLE_EQ(read("180 deg", Dimension::kAngle), std::numbers::pi);
  EXPECT_DOUBLE_EQ(read("20 kPa", Dimension::kPressure), 20000);
  EXPECT_DOUBLE_EQ(read("60 rpm", Dimension::kAngularSpeed), 2 * std::numbers::pi);
}

TEST(Units, BareNumbersAreSiWhereNoUnitIsRequired) {
  EXPECT_DOUBLE_EQ(read("0.5", Dimension::kLength), 0.5);
  EXPECT_DOUBLE_EQ(read("400", Dimension::kStiffness), 400);
  EXPECT_DOUBLE_EQ(read("-9.81", Dimension::kAcceleration), -9.81);
  EXPECT_DOUBLE_EQ(read("0", Dimension::kTime), 0);  // zero needs no unit
}

TEST(Units, ReadsFractionsAndIgnoresUnitCase) {
  EXPECT_DOUBLE_EQ(read("1/240 s", Dimension::kTime), 1.0 / 240);
  EXPECT_DOUBLE_EQ(read("1.2 HZ", Dimension::kFrequency), 1.2);
}

TEST(Units, RefusesAMissingRequiredUnit) {
  const std::string message = refusal("72", Dimension::kFrequency);
  EXPECT_TRUE(Contains(message, "units.yaml:3:7"));
  EXPECT_TRUE(Contains(message, "organs[0].body.x"));
  EXPECT_TRUE(Contains(message, "expected a frequency with a unit, e.g. \"72 bpm\" or \"1.2 Hz\""));
}

TEST(Units, RefusesAnUnknownUnitAndNamesTheAllowedOnes) {
  EXPECT_TRUE(Contains(refusal("3 furlongs", Dimension::kLength), "unknown unit 'furlongs'"));
  EXPECT_TRUE(Contains(refusal("3 furlongs", Dimension::kLength), "a length takes m, cm, mm"));
  EXPECT_TRUE(Contains(refusal("3 cm", Dimension::kNumber), "expected a plain number without a unit"));
}

TEST(Units, RefusesNonFiniteAndZeroDenominators) {
  EXPECT_TRUE(Contains(refusal("nan", Dimension::kNumber), "expected a finite number"));
  EXPECT_TRUE(Contains(refusal("inf m", Dimension::kLength), "expected a finite number"));
  EXPECT_TRUE(Contains(refusal("1/0 s", Dimension::kTime), "non-zero denominator"));
  EXPECT_TRUE(Contains(refusal("fast", Dimension::kTime), "expected a time"));
}

TEST(Units, RefusesNonScalars) {
  Node list;
  list.kind = Node::Kind::kList;
  EXPECT_THROW(parse_quantity(list, Dimension::kLength, "x"), Error);
  EXPECT_THROW(parse_integer(list, "x"), Error);
}

TEST(Units, ParsesWholeNumbersOnly) {
  EXPECT_EQ(parse_integer(scalar("42"), "n"), 42);
  EXPECT_EQ(parse_integer(scalar("+7"), "n"), 7);
  EXPECT_EQ(parse_integer(scalar("-3"), "n"), -3);
  EXPECT_THROW(parse_integer(scalar("4.5"), "n"), Error);
  EXPECT_THROW(parse_integer(scalar("4 s"), "n"), Error);
  try {
    parse_integer(scalar("99999999999999999999"), "n");
    FAIL() << "an out-of-range whole number was accepted";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "is too large"));
  }
}

TEST(Units, FormatsNumbersShortAndExact) {
  EXPECT_EQ(format_number(0.35), "0.35");
  EXPECT_EQ(format_number(1e9), "1e9");
  EXPECT_EQ(format_number(1e-5), "1e-5");
  EXPECT_EQ(format_number(1.0 / 240), "0.004166666667");
  EXPECT_EQ(format_number(-2), "-2");
}

TEST(Units, FormatsQuantitiesInTheDisplayUnit) {
  EXPECT_EQ(format_quantity(0.3, Dimension::kMass), "0.3 kg");
  EXPECT_EQ(format_quantity(40 * std::numbers::pi / 180, Dimension::kAngle), "40 deg");
  EXPECT_EQ(format_quantity(0.95, Dimension::kNumber), "0.95");
}

TEST(Units, DisplayUnitComesFirstAndRoundTrips) {
  for (Dimension d : {Dimension::kLength, Dimension::kMass, Dimension::kTime, Dimension::kFrequency,
                      Dimension::kAngle, Dimension::kPressure, Dimension::kAngularSpeed}) {
    const DimensionInfo& info = dimension_info(d);
    ASSERT_FALSE(info.units.empty()) << info.name;
    const double si = 1.25 * info.units[0].to_si;
    EXPECT_DOUBLE_EQ(read(format_quantity(si, d), d), si) << info.name;
  }
  EXPECT_TRUE(dimension_info(Dimension::kNumber).units.empty());
  EXPECT_TRUE(dimension_info(Dimension::kTime).unit_required);
  EXPECT_FALSE(dimension_info(Dimension::kLength).unit_required);
}

}  // namespace
}  // namespace systole::scene
