// The captions and chapter marks a video carries (encode/text_streams.h), round-tripped
// through libav: captions muxed as a WebVTT stream come back with their times and text,
// chapters land in the container with their titles and millisecond times.

#include "encode/text_streams.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "encode/video_writer.h"

extern "C" {
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
}

namespace systole::encode::detail {
namespace {

std::filesystem::path scratch() {
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / "text_streams";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TextStreams, CaptionsMuxedAsWebVttComeBackWithTheirTimesAndText) {
  const std::filesystem::path file = scratch() / "captions.vtt";
  const std::vector<TextCue> cues = {{0.5, 2.0, "Systole"}, {2.25, 4.0, "the ventricles {eject}\nsecond line"}};
  AVFormatContext* format = nullptr;
  ASSERT_GE(avformat_alloc_output_context2(&format, nullptr, "webvtt", file.c_str()), 0);
  {
    SubtitleStream subs(format, "webvtt", cues, "test");
    ASSERT_EQ(format->nb_streams, 1u);
    EXPECT_EQ(format->streams[0]->codecpar->codec_type, AVMEDIA_TYPE_SUBTITLE);
    ASSERT_GE(avio_open(&format->pb, file.c_str(), AVIO_FLAG_WRITE), 0);
    ASSERT_GE(avformat_write_header(format, nullptr), 0);
    subs.write(format);
    ASSERT_GE(av_write_trailer(format), 0);
  }
  avio_closep(&format->pb);
  avformat_free_context(format);

  const std::string text = read(file);
  EXPECT_NE(text.find("00:00.500 --> 00:02.000"), std::string::npos) << text;
  EXPECT_NE(text.find("00:02.250 --> 00:04.000"), std::string::npos) << text;
  EXPECT_NE(text.find("Systole"), std::string::npos) << text;
  // Braces would be ASS markup: they are kept as text (as parentheses), and the line break stays.
  EXPECT_NE(text.find("the ventricles (eject)\nsecond line"), std::string::npos) << text;
  EXPECT_LT(text.find("Systole"), text.find("the ventricles"));  // In order.
}

TEST(TextStreams, AnEncoderTheBuildLacksIsAnInternalError) {
  AVFormatContext* format = nullptr;
  ASSERT_GE(avformat_alloc_output_context2(&format, nullptr, "matroska", (scratch() / "x.mkv").c_str()), 0);
  try {
    SubtitleStream subs(format, "no-such-encoder", {{0, 1, "x"}}, "captions");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kInternal);
    EXPECT_EQ(std::string(e.what()).rfind("captions encoder:", 0), 0u) << e.what();
  }
  avformat_free_context(format);
}

TEST(TextStreams, ChaptersCarryTheirTitlesAndMillisecondTimes) {
  AVFormatContext* format = nullptr;
  ASSERT_GE(avformat_alloc_output_context2(&format, nullptr, "matroska", (scratch() / "chapters.mkv").c_str()), 0);
  const std::vector<ChapterMark> marks = {{0.0, 2.5, "Diastole"}, {2.5, 3.125, "Systole"}, {3.125, 10.0, "Rest"}};
  add_chapters(format, marks, "test");
  ASSERT_EQ(format->nb_chapters, 3u);
  for (unsigned i = 0; i < 3; ++i) {
    const AVChapter* c = format->chapters[i];
    EXPECT_EQ(c->time_base.num, 1);
    EXPECT_EQ(c->time_base.den, 1000);
    EXPECT_EQ(c->start, std::llround(marks[i].start_s * 1000));
    EXPECT_EQ(c->end, std::llround(marks[i].end_s * 1000));
    const AVDictionaryEntry* title = av_dict_get(c->metadata, "title", nullptr, 0);
    ASSERT_NE(title, nullptr);
    EXPECT_EQ(std::string(title->value), marks[i].title);
  }
  avformat_free_context(format);
}

}  // namespace
}  // namespace systole::encode::detail
