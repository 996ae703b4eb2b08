#include "clip/progress.h"

#include <gtest/gtest.h>

#include <string>

namespace systole::clip {
namespace {

TEST(Progress, JsonLinesNameTheJobQuotedAndAlwaysReportTheLastFrame) {
  testing::internal::CaptureStdout();
  Progress p("heart \"fast\"", 3, ProgressStyle::kJson);
  p.update(1);  // The first line is drawn at once.
  p.update(2);  // Within half a second of the first: skipped.
  p.update(3);  // The last frame is always reported.
  p.finish();
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(out.find("{\"job\": \"heart \\\"fast\\\"\", \"frame\": 1, \"frames\": 3, "), 0u) << out;
  EXPECT_EQ(out.find("\"frame\": 2,"), std::string::npos) << out;
  EXPECT_NE(out.find("\"frame\": 3, \"frames\": 3, "), std::string::npos) << out;
  EXPECT_EQ(out.back(), '\n');
}

TEST(Progress, NoneWritesNothingAndTerminalWritesOnlyToStderr) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  Progress quiet("a", 2, ProgressStyle::kNone);
  quiet.update(2);
  quiet.finish();
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  testing::internal::CaptureStderr();
  Progress line("b", 2, ProgressStyle::kTerminal);
  line.update(2);
  line.finish();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(err.find("b: frame 2/2  100%"), std::string::npos) << err;
  EXPECT_NE(err.find("\r\033[K"), std::string::npos);  // finish() clears the line.
}

}  // namespace
}  // namespace systole::clip
