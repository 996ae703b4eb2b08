// A scene cannot exhaust the machine: aliases that multiply ("billion laughs"), in the file
// or in a -D value, hundreds of thousands of keys, and nesting a megabyte deep are refused
// with exit 65 and a message that names the bound and the line, after linear work.

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "scene/tree.h"
#include "scene_test_util.h"

namespace systole::scene::testing {
namespace {

/// Nine levels of nine aliases each: 9^9 = 387 million values once expanded.
std::string laughs(const std::string& indent) {
  std::string yaml = indent + "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string prev = "*a" + std::to_string(level - 1);
    yaml += indent + "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + prev;
    for (int k = 1; k < 9; ++k) yaml += ", " + prev;
    yaml += "]\n";
  }
  return yaml;
}

/// Runs `load` and returns its failure and how long it took (a regression back to
/// exponential or quadratic work would take minutes; CTest's timeout stops it).
template <class F>
std::pair<Failure, double> timed(F&& load) {
  const auto t0 = std::chrono::steady_clock::now();
  Failure f = load();
  return {f, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

TEST(ParseLimits, AnAliasBombInTheFileIsRefused) {
  const std::string yaml = std::string(kMinimalOrgans) + "bomb:\n" + laughs("  ");
  const auto [f, seconds] = timed([&] { return load_error(yaml); });
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("scenes/test.yaml:"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("more than 100000 values"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("aliases"), std::string::npos) << f.message;
  EXPECT_LT(seconds, 10.0);
}

TEST(ParseLimits, AnAliasBombInAnOverrideIsRefused) {
  std::string value = "{";
  const std::string lines = laughs("");
  // The same bomb as one flow map: "a0: &a0 [...]\n..." -> "{a0: &a0 [...], ...}".
  for (std::size_t at = 0, next; at < lines.size(); at = next + 1) {
    next = lines.find('\n', at);
    value += (value.size() > 1 ? ", " : "") + lines.substr(at, next - at);
  }
  value += "}";
  const auto [f, seconds] = timed([&] { return load_error(kMinimalOrgans, {"organs.0.mesh=" + value}); });
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("-D organs.0.mesh="), std::string::npos) << f.message.substr(0, 300);
  EXPECT_NE(f.message.find("more than 100000 values"), std::string::npos) << f.message.substr(0, 300);
  EXPECT_LT(seconds, 10.0);
}

/// `keys` distinct keys in the camera map, then a repeat of key7.
std::string many_keys(int keys) {
  std::string yaml = std::string(kMinimalOrgans) + "camera:\n";
  for (int k = 0; k < keys; ++k) yaml += "  key" + std::to_string(k) + ": 1\n";
  return yaml + "  key7: 2\n";
}

TEST(ParseLimits, TwoHundredThousandKeysAreRefusedUnparsed) {
  const auto [f, seconds] = timed([&] { return load_error(many_keys(200000)); });
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("has more than 100000 values"), std::string::npos) << f.message;
  EXPECT_LT(seconds, 10.0);
}

TEST(ParseLimits, DuplicateKeysAreFoundInLinearTime) {
  // 90,000 keys: the pairwise check this replaced took about 20 s here.
  const auto [f, seconds] = timed([&] { return load_error(many_keys(90000)); });
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("duplicate key 'key7' (first written at line 12)"), std::string::npos) << f.message;
  EXPECT_LT(seconds, 10.0);
}

TEST(ParseLimits, DeepNestingIsRefusedBeforeTheParserRecurses) {
  const std::string flow = std::string(kMinimalOrgans) + "deep: " + std::string(1 << 20, '[') + "\n";
  const auto [f, seconds] = timed([&] { return load_error(flow); });
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("scenes/test.yaml:4:"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("nested more than 64 deep"), std::string::npos) << f.message;
  EXPECT_LT(seconds, 10.0);

  std::string block = kMinimalOrgans;
  for (int level = 0; level < 100; ++level) block += std::string(2 * level, ' ') + "k:\n";
  const Failure b = load_error(block);
  EXPECT_EQ(b.code, ExitCode::kDataError);
  EXPECT_NE(b.message.find("nested more than 64 deep"), std::string::npos) << b.message;
}

TEST(ParseLimits, AnOversizedSceneIsRefusedUnread) {
  const std::string yaml = std::string(kMinimalOrgans) + "# " + std::string(kMaxSceneBytes, 'x') + "\n";
  const Failure f = load_error(yaml);
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("a scene may be at most"), std::string::npos) << f.message;
}

TEST(ParseLimits, TheShippedKindOfSceneIsWellWithinTheBounds) {
  // Aliases are still welcome where they do not multiply.
  const std::string yaml = std::string(kMinimalOrgans) +
                           "camera: {position: &eye [0, 0, 0.4], target: [0, 0, 0]}\n"
                           "views:\n  - {camera: {position: *eye}}\n  - {camera: {position: *eye}}\n";
  EXPECT_TRUE(load_error(yaml).message.empty()) << load_error(yaml).message;
}

}  // namespace
}  // namespace systole::scene::testing
