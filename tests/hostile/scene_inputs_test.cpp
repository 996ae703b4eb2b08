// ctest-labels: no-sanitizers
// The hostile-input corpus, scenes (tests/hostile/README.md): the scenes that exhausted the
// machine before the parse bounds (docs/robustness.md, "Resource limits"), run through the
// real command line: an alias bomb in the file and in a -D value, 200,000 keys, a megabyte
// of nesting, long -D values, a 4 GiB file, bytes that are not UTF-8. Each must be refused
// with exit 65 within 2 s of CPU time and under 200 MB of peak memory, as the process itself
// measures them (wait4's rusage). CPU time, not wall time, so a busy machine does not make
// the test flaky; no sanitizers, whose shadow memory would be measured too.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/measure.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// Nine levels of nine aliases each: 387 million values once expanded.
std::string laughs(const std::string& indent, const std::string& separator) {
  std::string yaml = indent + "a0: &a0 [x, x, x, x, x, x, x, x, x]";
  for (int level = 1; level <= 9; ++level) {
    const std::string prev = "*a" + std::to_string(level - 1);
    yaml += separator + indent + "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + prev;
    for (int k = 1; k < 9; ++k) yaml += ", " + prev;
    yaml += "]";
  }
  return yaml;
}

const char* const kOrgans = "organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n";

void expect_refused_cheaply(const std::string& what, const Measured& m) {
  SCOPED_TRACE(what);
  EXPECT_EQ(m.exit_code, 65);
  EXPECT_LT(m.cpu_s, 2.0) << "seconds of CPU";
  EXPECT_LT(m.peak_mb, 200.0) << "MB at peak";
  std::printf("[ bounds   ] %s: exit %d, %.2f s CPU, %.0f MB peak\n", what.c_str(), m.exit_code, m.cpu_s, m.peak_mb);
}

TEST(ParseBounds, HostileScenesAreRefusedWithinTwoSecondsAndTwoHundredMegabytes) {
  const fs::path dir = scratch("parse_bounds");
  write_file(dir / "bomb.yaml", std::string(kOrgans) + "bomb:\n" + laughs("  ", "\n") + "\n");
  expect_refused_cheaply("alias bomb in the file", measure({"validate", (dir / "bomb.yaml").string()}));

  write_file(dir / "plain.yaml", kOrgans);
  expect_refused_cheaply("alias bomb in -D", measure({"validate", (dir / "plain.yaml").string(), "-D",
                                                      "organs.0.mesh={" + laughs("", ", ") + "}"}));

  std::string keys = std::string(kOrgans) + "camera:\n";
  for (int k = 0; k < 200000; ++k) keys += "  key" + std::to_string(k) + ": 1\n";
  write_file(dir / "keys.yaml", keys);
  expect_refused_cheaply("200,000 keys", measure({"validate", (dir / "keys.yaml").string()}));

  write_file(dir / "deep.yaml", std::string(kOrgans) + "deep: " + std::string(1 << 20, '[') + "\n");
  expect_refused_cheaply("a megabyte of nesting", measure({"validate", (dir / "deep.yaml").string()}));
}

TEST(ParseBounds, LongDefineValuesCostMemoryInProportionAndAreNotEchoedWhole) {
  const fs::path dir = scratch("parse_bounds_define");
  write_file(dir / "plain.yaml", kOrgans);
  std::string list = "camera.position=[";
  for (int k = 0; k < 20000; ++k) list += "1, ";
  list += "1]";
  expect_refused_cheaply("a -D list of 20,000 items", measure({"validate", (dir / "plain.yaml").string(), "-D", list}));
  std::string map = "camera={";
  for (int k = 0; k < 9000; ++k) map += "key" + std::to_string(k) + ": 1, ";
  map += "end: 1}";
  expect_refused_cheaply("a -D map of 9,000 keys", measure({"validate", (dir / "plain.yaml").string(), "-D", map}));
  const auto r = run(systole() + " validate " + (dir / "plain.yaml").string() + " -D '" + map + "'");
  EXPECT_EQ(r.exit_code, 65) << r.output.substr(0, 500);
  EXPECT_NE(r.output.find("-D camera={key0: 1, key1: 1,"), std::string::npos) << r.output.substr(0, 500);
  EXPECT_NE(r.output.find("(" + std::to_string(map.size()) + " characters)"), std::string::npos) << r.output.substr(0, 500);
  EXPECT_EQ(r.output.find("key8999"), std::string::npos) << "the value is not echoed whole";
}

TEST(ParseBounds, A120KilobyteDefineUnderAThreeGigabyteCapIsAParseErrorNotOutOfMemory) {
  const fs::path dir = scratch("parse_bounds_capped");
  write_file(dir / "plain.yaml", kOrgans);
  std::string list = "organs.0.regions=[";
  for (int k = 0; k < 17000; ++k) list += "123456,";
  list += "1]";
  ASSERT_GT(list.size(), 119000u);
  const Measured m = measure({"validate", (dir / "plain.yaml").string(), "-D", list}, 3LL << 30);
  expect_refused_cheaply("a 120 KB -D list under a 3 GB cap", m);
  EXPECT_NE(m.errors.find("organs[0].regions: expected 0..256 items; got 17001"), std::string::npos) << m.errors.substr(0, 500);
  EXPECT_EQ(m.errors.find("frame size"), std::string::npos) << "no advice that does not apply";
}

TEST(ParseBounds, AGarbageSceneIsRefusedWithItsBytesEscaped) {
  const fs::path dir = scratch("parse_bounds_garbage");
  write_file(dir / "garbage.yaml", "organs:\n  - name: \xff\xfeheart\x01\n");
  const Measured m = measure({"validate", (dir / "garbage.yaml").string()});
  expect_refused_cheaply("a scene with bytes that are not UTF-8", m);
  EXPECT_NE(m.errors.find("got \"\\xff\\xfeheart\\x01\""), std::string::npos) << m.errors;
}

TEST(ParseBounds, AHugeSceneFileIsRefusedByItsSizeBeforeItIsRead) {
  const fs::path dir = scratch("parse_bounds_huge");
  const fs::path huge = dir / "huge.yaml";
  write_file(huge, kOrgans);
  fs::resize_file(huge, std::uintmax_t{4} << 30);  // Sparse: 4 GiB that take no disk.
  expect_refused_cheaply("a 4 GiB scene file", measure({"validate", huge.string()}));
  const auto r = run(systole() + " validate " + huge.string());
  EXPECT_NE(r.output.find(huge.string() + ": is 4294967296 bytes; a scene may be at most 16777216"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace systole::test
