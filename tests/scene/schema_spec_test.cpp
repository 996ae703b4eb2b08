// The schema's value readers (scene/schema/spec.h): quantities with their units and ranges,
// booleans, names, screen text, vectors, directions and colours, each read from YAML and
// each refusing what it must, with the key's path in the message.

#include "scene/schema/spec.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "scene/tree.h"

namespace systole::scene::schema {
namespace {

template <class T>
T read(const ValueSpec<T>& spec, const std::string& yaml) {
  const Node root = parse_yaml("key: " + yaml + "\n", "s.yaml");
  T out{};
  spec.read(*root.find("key"), out, "organs[0].key", Context{});
  return out;
}

/// The message reading `yaml` with `spec` throws (Error(kDataError)), or "".
template <class T>
std::string refusal(const ValueSpec<T>& spec, const std::string& yaml) {
  try {
    read(spec, yaml);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError) << yaml;
    return e.what();
  }
  return "";
}

TEST(SchemaSpec, QuantitiesReadInAnyUnitOfTheirDimension) {
  const auto length = quantity(Dimension::kLength, any());
  EXPECT_DOUBLE_EQ(read(length, "5 cm"), 0.05);
  EXPECT_DOUBLE_EQ(read(length, "12 mm"), 0.012);
  EXPECT_DOUBLE_EQ(read(length, "0.3"), 0.3);  // A bare length is metres.
  EXPECT_DOUBLE_EQ(read(quantity(Dimension::kMass, any()), "250 g"), 0.25);
  EXPECT_DOUBLE_EQ(read(quantity(Dimension::kTime, any()), "160 ms"), 0.16);
  EXPECT_DOUBLE_EQ(read(quantity(Dimension::kFrequency, any()), "72 bpm"), 1.2);
  EXPECT_NEAR(read(quantity(Dimension::kAngle, any()), "180 deg"), 3.14159265358979, 1e-12);
  EXPECT_DOUBLE_EQ(read(quantity(Dimension::kPressure, any()), "3 kPa"), 3000);
  // A unit of another dimension is refused.
  EXPECT_NE(refusal(length, "5 kg"), "");
}

TEST(SchemaSpec, ARangeIsCheckedInTheDisplayUnitAndTheMessageShowsBoth) {
  const auto rate = quantity(Dimension::kFrequency, closed(0.1, 5));  // Hz
  EXPECT_DOUBLE_EQ(read(rate, "300 bpm"), 5.0);                       // On the closed end.
  const std::string message = refusal(rate, "1500 bpm");
  EXPECT_NE(message.find("1500 bpm = "), std::string::npos) << message;
  EXPECT_NE(message.find("[0.1, 5] Hz"), std::string::npos) << message;
  EXPECT_NE(message.find("organs[0].key"), std::string::npos) << message;  // Where.
  const auto share = number(open_closed(0, 1));
  EXPECT_NE(refusal(share, "0"), "");  // Open at 0.
  EXPECT_DOUBLE_EQ(read(share, "1"), 1.0);
  EXPECT_NE(refusal(share, "1.5"), "");
}

TEST(SchemaSpec, RangesKnowTheirEnds) {
  EXPECT_TRUE(closed(0, 1).contains(0));
  EXPECT_TRUE(closed(0, 1).contains(1));
  EXPECT_FALSE(open(0, 1).contains(0));
  EXPECT_FALSE(open(0, 1).contains(1));
  EXPECT_TRUE(open(0, 1).contains(0.5));
  EXPECT_FALSE(any().bounded());
  EXPECT_TRUE(any().contains(-1e300));
  EXPECT_EQ(open_closed(0, 2).text("m"), "(0, 2] m");
}

TEST(SchemaSpec, WholeNumbersStayInTheirBounds) {
  const auto count = whole<int>(1, 8);
  EXPECT_EQ(read(count, "8"), 8);
  EXPECT_NE(refusal(count, "9"), "");
  EXPECT_NE(refusal(count, "0"), "");
  EXPECT_NE(refusal(count, "2.5"), "");
}

TEST(SchemaSpec, BooleansAreTrueOrFalseOnly) {
  EXPECT_TRUE(read(boolean(), "true"));
  EXPECT_FALSE(read(boolean(), "False"));
  EXPECT_NE(refusal(boolean(), "yes"), "");
  EXPECT_NE(refusal(boolean(), "1"), "");
  EXPECT_NE(refusal(boolean(), "[true]"), "");
}

TEST(SchemaSpec, NamesArePlainWordsNeverOnlyDigits) {
  EXPECT_EQ(read(name_text(), "left_ventricle"), "left_ventricle");
  EXPECT_EQ(read(name_text(), "lv-2"), "lv-2");
  EXPECT_NE(refusal(name_text(), "'12'"), "");  // Would read as a list index in -D.
  EXPECT_NE(refusal(name_text(), "'left ventricle'"), "");
  EXPECT_NE(refusal(name_text(), "a.b"), "");  // A dot would split a -D path.
  EXPECT_NE(refusal(name_text(), "''"), "");
}

TEST(SchemaSpec, ScreenTextHasALengthAndMayBeOneLine) {
  EXPECT_EQ(read(screen_text(10, false), "\"a\\nb\""), "a\nb");
  EXPECT_EQ(read(screen_text(10, true), "Systole"), "Systole");
  EXPECT_NE(refusal(screen_text(10, true), "\"a\\nb\""), "");
  EXPECT_NE(refusal(screen_text(5, false), "Diastole"), "");
  EXPECT_NE(refusal(screen_text(5, false), "''"), "");
}

TEST(SchemaSpec, VectorsTakeThreeQuantities) {
  const Eigen::Vector3d v = read(vec3(Dimension::kLength), "[1 cm, 0, -2 mm]");
  EXPECT_TRUE(v.isApprox(Eigen::Vector3d(0.01, 0, -0.002)));
  EXPECT_NE(refusal(vec3(Dimension::kLength), "[1, 2]"), "");
  EXPECT_NE(refusal(vec3(Dimension::kLength), "1"), "");
  EXPECT_TRUE(read(direction(), "[0, 2, 0]").isApprox(Eigen::Vector3d(0, 2, 0)));
  EXPECT_NE(refusal(direction(), "[0, 0, 0]"), "");
}

TEST(SchemaSpec, ColoursAreHexOrUnitChannels) {
  const auto red = read(color(), "\"#ff8000\"");
  EXPECT_DOUBLE_EQ(red.x(), 1.0);
  EXPECT_DOUBLE_EQ(red.y(), 128 / 255.0);
  EXPECT_DOUBLE_EQ(red.z(), 0.0);
  const auto grey = read(color(), "[0.5, 0.5, 0.5]");
  EXPECT_DOUBLE_EQ(grey.x(), 0.5);
  EXPECT_NE(refusal(color(), "[0.5, 1.5, 0]"), "");
  EXPECT_NE(refusal(color(), "\"#ff80\""), "");
  EXPECT_NE(refusal(color(), "\"#gg0000\""), "");
  // An unquoted # starts a YAML comment: the message says so.
  const std::string message = refusal(color(), "#ff0000");
  EXPECT_NE(message.find("quotes"), std::string::npos) << message;
}

TEST(SchemaSpec, DisplayUnitsAreTheDimensionsFirst) {
  EXPECT_EQ(display_unit(Dimension::kNumber), "");
  EXPECT_EQ(display_unit(Dimension::kFrequency), "Hz");
  EXPECT_EQ(display_unit(Dimension::kTime), "s");
}

}  // namespace
}  // namespace systole::scene::schema
