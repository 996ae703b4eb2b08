#include "encode/versions.h"

#include <gtest/gtest.h>

#include <regex>

namespace systole::encode {
namespace {

TEST(Versions, LibrariesAreNamedWithTheirVersion) {
  const std::vector<std::string> lines = library_versions();
  ASSERT_EQ(lines.size(), 5u);
  const std::regex line(R"((libavcodec|libavformat|libavutil|libswscale|libpng) \d+\.\d+\.\d+)");
  for (const auto& l : lines) EXPECT_TRUE(std::regex_match(l, line)) << l;
  EXPECT_EQ(lines[0].rfind("libavcodec ", 0), 0u);
  EXPECT_EQ(lines[4].rfind("libpng ", 0), 0u);
}

TEST(Versions, Libx264IsTheFirstH264Encoder) {
  const std::vector<std::string> names = h264_encoders();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "libx264");
  for (const auto& n : names) EXPECT_FALSE(n.empty());
}

TEST(Versions, EveryOutputFormatHasItsEncoder) {
  const std::vector<std::string> expected = {"mp4 (libx264)", "mkv (ffv1)", "webm (libvpx-vp9)", "gif (gif)"};
  EXPECT_EQ(output_formats(), expected);
}

}  // namespace
}  // namespace systole::encode
