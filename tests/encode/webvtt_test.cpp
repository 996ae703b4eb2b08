// Captions as WebVTT (encode/webvtt.h): timestamps in the format the W3C spec requires, cues
// numbered in order, text escaped.

#include "encode/webvtt.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace systole::encode {
namespace {

TEST(WebVtt, TimestampsAreHoursMinutesSecondsAndMilliseconds) {
  EXPECT_EQ(webvtt_time(0), "00:00:00.000");
  EXPECT_EQ(webvtt_time(62.345), "00:01:02.345");
  EXPECT_EQ(webvtt_time(3600), "01:00:00.000");
  EXPECT_EQ(webvtt_time(3 * 3600 + 59 * 60 + 59.999), "03:59:59.999");
  // Rounded to the millisecond, carrying into the seconds and minutes.
  EXPECT_EQ(webvtt_time(59.9996), "00:01:00.000");
  EXPECT_EQ(webvtt_time(1.0004), "00:00:01.000");
}

TEST(WebVtt, EveryTimestampHasTheSpecsShape) {
  const std::regex shape(R"(\d\d:[0-5]\d:[0-5]\d\.\d\d\d)");
  for (double t = 0; t < 7300; t += 97.3217) EXPECT_TRUE(std::regex_match(webvtt_time(t), shape)) << t;
}

TEST(WebVtt, AFileIsTheHeaderThenNumberedEscapedCues) {
  const std::vector<TextCue> cues = {{0.5, 2.0, "Systole"}, {2.0, 3.25, "Ejection <fast> & strong\nsecond line"}};
  EXPECT_EQ(webvtt_text(cues),
            "WEBVTT\n"
            "\n1\n00:00:00.500 --> 00:00:02.000\nSystole\n"
            "\n2\n00:00:02.000 --> 00:00:03.250\nEjection &lt;fast&gt; &amp; strong\nsecond line\n");
  EXPECT_EQ(webvtt_text({}), "WEBVTT\n");
}

TEST(WebVtt, TheWrittenFileIsTheText) {
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / "webvtt";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::vector<TextCue> cues = {{1, 2, "one"}, {2, 4, "two"}};
  write_webvtt(dir / "captions.vtt", cues);
  std::ifstream in(dir / "captions.vtt", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), webvtt_text(cues));
}

}  // namespace
}  // namespace systole::encode
