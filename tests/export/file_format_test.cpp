// `systole export`'s choice of format by extension, its loop, and its --max-error parsing
// (export/exporter.h).

#include "export/exporter.h"

#include <gtest/gtest.h>

#include "support/error_code.h"

#include "common/error.h"

namespace systole::exporter {
namespace {

using systole::test::code_of;

TEST(FileFormat, TheExtensionPicksTheFormatInAnyCase) {
  EXPECT_EQ(file_format("out/heart.glb"), FileFormat::kGlb);
  EXPECT_EQ(file_format("heart.GLTF"), FileFormat::kGltf);
  EXPECT_EQ(file_format("a.b/heart.pc2"), FileFormat::kPc2);
  EXPECT_EQ(file_format("heart.Mdd"), FileFormat::kMdd);
  EXPECT_EQ(file_format("heart.pvd"), FileFormat::kPvd);
  EXPECT_EQ(file_format("heart.usda"), FileFormat::kUsda);
  EXPECT_EQ(file_format("heart.html"), FileFormat::kHtml);
}

TEST(FileFormat, AnUnknownExtensionIsAUsageErrorListingTheKnownOnes) {
  for (const char* file : {"heart.obj", "heart", "heart.glb.bak", ".glb/heart", "heart.htm"}) {
    try {
      file_format(file);
      ADD_FAILURE() << file << ": no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::kUsage) << file;
      EXPECT_NE(std::string(e.what()).find(known_extensions()), std::string::npos) << e.what();
    }
  }
}

TEST(FileFormat, EveryKnownExtensionIsAccepted) {
  // The help text's list and what file_format accepts are the same set.
  const std::string list = known_extensions();
  std::size_t start = 0, count = 0;
  while (start < list.size()) {
    std::size_t end = list.find(", ", start);
    if (end == std::string::npos) end = list.size();
    const std::string ext = list.substr(start, end - start);
    EXPECT_EQ(ext.front(), '.') << ext;
    EXPECT_EQ(code_of([&] { file_format("heart" + ext); }), ExitCode::kOk) << ext;
    ++count;
    start = end + 2;
  }
  EXPECT_EQ(count, 7u);
}

TEST(FileFormat, OnlyTheCompactMorphFormatsNeedTheLoop) {
  ExportOptions compact, frames;
  compact.encoding = Encoding::kCompact;
  frames.encoding = Encoding::kFrames;
  for (FileFormat f : {FileFormat::kGlb, FileFormat::kGltf, FileFormat::kHtml}) {
    EXPECT_TRUE(needs_loop(f, compact));
    EXPECT_FALSE(needs_loop(f, frames));
  }
  // Point caches, VTK and USD hold every frame whatever the encoding.
  for (FileFormat f : {FileFormat::kPc2, FileFormat::kMdd, FileFormat::kPvd, FileFormat::kUsda}) {
    EXPECT_FALSE(needs_loop(f, compact));
    EXPECT_FALSE(needs_loop(f, frames));
  }
}

TEST(FileFormat, TheLoopOverridesTurnTheLoopOn) {
  const std::vector<std::string> overrides = loop_overrides();
  bool loop = false;
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    ASSERT_NE(eq, std::string::npos) << o;  // -D key=value
    EXPECT_EQ(o.rfind("output.", 0), 0u) << o;
    if (o.substr(0, eq) == "output.loop") loop = o.substr(eq + 1) == "true";
  }
  EXPECT_TRUE(loop);
}

TEST(FileFormat, PercentParsesWithOrWithoutTheSign) {
  EXPECT_DOUBLE_EQ(parse_percent("2%"), 2.0);
  EXPECT_DOUBLE_EQ(parse_percent("2 %"), 2.0);
  EXPECT_DOUBLE_EQ(parse_percent("2"), 2.0);
  EXPECT_DOUBLE_EQ(parse_percent("0.5%"), 0.5);
  EXPECT_DOUBLE_EQ(parse_percent("100"), 100.0);
}

TEST(FileFormat, PercentOutsideZeroToAHundredOrNotANumberIsRefused) {
  for (const char* text : {"0", "0%", "-1%", "100.5", "150%", "", "%", "two", "2x%", "nan", "inf"}) {
    EXPECT_EQ(code_of([&] { parse_percent(text); }), ExitCode::kUsage) << '"' << text << '"';
  }
}

}  // namespace
}  // namespace systole::exporter
