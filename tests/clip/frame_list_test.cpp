// Frame lists: the render-farm forms, sorted and de-duplicated, and errors that teach the syntax.

#include "clip/frame_list.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace systole::clip {
namespace {

using Frames = std::vector<int>;

TEST(FrameList, SingleFramesRangesAndSteps) {
  EXPECT_EQ(parse_frame_list("0,30,60", 300), (Frames{0, 30, 60}));
  EXPECT_EQ(parse_frame_list("10..20", 300), (Frames{10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20}));
  const auto every_tenth = parse_frame_list("0..299:10", 300);
  ASSERT_EQ(every_tenth.size(), 30u);
  EXPECT_EQ(every_tenth.front(), 0);
  EXPECT_EQ(every_tenth.back(), 290);
  EXPECT_EQ(parse_frame_list("7", 8), (Frames{7}));
  EXPECT_EQ(parse_frame_list("3..3", 8), (Frames{3}));
}

TEST(FrameList, DeadlineAndNukeSpellings) {
  EXPECT_EQ(parse_frame_list("10-12", 300), (Frames{10, 11, 12}));
  EXPECT_EQ(parse_frame_list("0-10x5", 300), (Frames{0, 5, 10}));
}

TEST(FrameList, SortedWithoutDuplicatesAndSpacesAllowed) {
  EXPECT_EQ(parse_frame_list("5, 1 ,5,2..3, 3", 10), (Frames{1, 2, 3, 5}));
  EXPECT_EQ(parse_frame_list("0..4:2,1..5:2", 10), (Frames{0, 1, 2, 3, 4, 5}));
}

void expect_usage_error(const std::string& list, const std::string& expected_text, int frame_count = 300) {
  try {
    parse_frame_list(list, frame_count);
    ADD_FAILURE() << "'" << list << "' was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kUsage) << list;
    EXPECT_NE(std::string(e.what()).find(expected_text), std::string::npos) << e.what();
  }
}

TEST(FrameList, BadSyntaxIsAUsageErrorListingTheForms) {
  for (const char* bad : {"", "a", "1..", "..3", "1..5:", "1,,2", "1,", "-1", "1.5", "1..5:x", "99999999999", "0x10",
                          "1..2..3", "+4"}) {
    expect_usage_error(bad, "Accepted forms: N (one frame), A..B");
  }
  expect_usage_error("3..1", "ends before it starts");
  expect_usage_error("1..5:0", "step of 1 or more");
}

TEST(FrameList, FramesPastTheEndNameTheClipsFrameCount) {
  expect_usage_error("300", "frame 300 is past the clip's end: it has 300 frames (0..299)");
  expect_usage_error("0..300", "it has 300 frames");
  expect_usage_error("0..2000000000", "it has 300 frames");  // checked before expanding
  EXPECT_EQ(parse_frame_list("0..299", 300).size(), 300u);
}

TEST(FrameList, ConsecutiveFramesMakeAClip) {
  EXPECT_TRUE(is_contiguous({4, 5, 6}));
  EXPECT_TRUE(is_contiguous({9}));
  EXPECT_FALSE(is_contiguous({4, 6}));
  EXPECT_FALSE(is_contiguous({}));
}

}  // namespace
}  // namespace systole::clip
