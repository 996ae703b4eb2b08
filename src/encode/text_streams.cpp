#include "encode/text_streams.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "encode/av_error.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/mem.h>
}

namespace systole::encode::detail {
namespace {

// The ASS header the text encoders parse (what libavcodec's ff_ass_subtitle_header_default
// writes); they take each cue as an ASS dialogue line.
constexpr const char* kAssHeader =
    "[Script Info]\r\nScriptType: v4.00+\r\nPlayResX: 384\r\nPlayResY: 288\r\nScaledBorderAndShadow: yes\r\n\r\n"
    "[V4+ Styles]\r\nFormat: Name, Fontname, Fontsize, PrimaryColour, SecondaryColour, OutlineColour, BackColour, Bold, "
    "Italic, Underline, StrikeOut, ScaleX, ScaleY, Spacing, Angle, BorderStyle, Outline, Shadow, Alignment, MarginL, "
    "MarginR, MarginV, Encoding\r\nStyle: Default,Arial,16,&Hffffff,&Hffffff,&H0,&H0,0,0,0,0,100,100,0,0,1,1,0,2,10,10,"
    "10,0\r\n\r\n[Events]\r\nFormat: Layer, Start, End, Style, Name, MarginL, MarginR, MarginV, Effect, Text\r\n";

/// A caption as an ASS dialogue line's text: line breaks become \N; braces (ASS override
/// blocks) and backslashes (escapes) would be read as markup, so they become ( ) and /.
std::string ass_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += "\\N";
    else if (c == '{') out += '(';
    else if (c == '}') out += ')';
    else if (c == '\\') out += '/';
    else out += c;
  }
  return out;
}

std::int64_t milliseconds(double s) { return static_cast<std::int64_t>(std::llround(s * 1000.0)); }

}  // namespace

SubtitleStream::SubtitleStream(AVFormatContext* format, const char* encoder, const std::vector<TextCue>& cues,
                               std::string label)
    : label_(std::move(label)) {
  const AVCodec* av_codec = avcodec_find_encoder_by_name(encoder);
  if (av_codec == nullptr) throw Error(ExitCode::kInternal, label_ + " encoder: this FFmpeg build has no " + encoder + " encoder");
  AVCodecContext* text = avcodec_alloc_context3(av_codec);
  if (text == nullptr) throw Error(ExitCode::kInternal, label_ + " encoder: out of memory");
  text->time_base = AVRational{1, 1000};
  text->subtitle_header = reinterpret_cast<std::uint8_t*>(av_strdup(kAssHeader));
  text->subtitle_header_size = static_cast<int>(std::strlen(kAssHeader));
  text->flags |= AV_CODEC_FLAG_BITEXACT;
  int err = avcodec_open2(text, av_codec, nullptr);
  std::vector<std::uint8_t> buffer(1 << 16);
  std::string failure;
  if (err < 0) failure = std::string("cannot open ") + encoder + ": " + av_error_text(err);
  for (std::size_t i = 0; i < cues.size() && failure.empty(); ++i) {
    const TextCue& cue = cues[i];
    std::string line = "0,0,Default,,0,0,0,," + ass_text(cue.text);
    AVSubtitleRect rect{};
    rect.type = SUBTITLE_ASS;
    rect.ass = line.data();
    AVSubtitleRect* rects[1] = {&rect};
    AVSubtitle sub{};
    sub.num_rects = 1;
    sub.rects = rects;
    sub.start_display_time = 0;
    sub.end_display_time = static_cast<std::uint32_t>(milliseconds(cue.to_s) - milliseconds(cue.from_s));
    sub.pts = milliseconds(cue.from_s) * 1000;  // AV_TIME_BASE
    const int n = avcodec_encode_subtitle(text, buffer.data(), static_cast<int>(buffer.size()), &sub);
    if (n < 0) {
      failure = std::string(encoder) + " refused caption " + std::to_string(i) + ": " + av_error_text(n);
      break;
    }
    AVPacket* p = av_packet_alloc();
    if (p == nullptr || av_new_packet(p, n) < 0) {
      av_packet_free(&p);
      failure = "out of memory";
      break;
    }
    std::memcpy(p->data, buffer.data(), static_cast<std::size_t>(n));
    p->pts = p->dts = milliseconds(cue.from_s);
    p->duration = milliseconds(cue.to_s) - milliseconds(cue.from_s);
    p->flags |= AV_PKT_FLAG_KEY;
    packets_.push_back(p);
  }
  if (failure.empty()) {
    stream_ = avformat_new_stream(format, nullptr);
    if (stream_ == nullptr || avcodec_parameters_from_context(stream_->codecpar, text) < 0) {
      failure = "cannot add a subtitle stream";
    } else {
      stream_->time_base = AVRational{1, 1000};
      av_dict_set(&stream_->metadata, "language", "eng", 0);
    }
  }
  avcodec_free_context(&text);
  if (!failure.empty()) {
    for (AVPacket*& p : packets_) av_packet_free(&p);  // No destructor runs for a throwing constructor.
    throw Error(ExitCode::kInternal, label_ + " encoder: " + failure);
  }
}

SubtitleStream::~SubtitleStream() {
  for (AVPacket*& p : packets_) av_packet_free(&p);
}

void SubtitleStream::write(AVFormatContext* format) {
  for (AVPacket*& p : packets_) {
    av_packet_rescale_ts(p, AVRational{1, 1000}, stream_->time_base);
    p->stream_index = stream_->index;
    const int err = av_interleaved_write_frame(format, p);
    av_packet_free(&p);
    if (err < 0) throw Error(ExitCode::kIoError, label_ + " encoder: cannot write a caption: " + av_error_text(err));
  }
  packets_.clear();
}

void add_chapters(AVFormatContext* format, const std::vector<ChapterMark>& chapters, const std::string& label) {
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    const ChapterMark& mark = chapters[i];
    auto* chapter = static_cast<AVChapter*>(av_mallocz(sizeof(AVChapter)));
    void* grown = chapter == nullptr ? nullptr : av_realloc_array(format->chapters, format->nb_chapters + 1, sizeof(AVChapter*));
    if (grown == nullptr) {
      av_free(chapter);
      throw Error(ExitCode::kInternal, label + " encoder: out of memory");
    }
    format->chapters = static_cast<AVChapter**>(grown);
    format->chapters[format->nb_chapters++] = chapter;  // Freed with the format context.
    chapter->id = static_cast<std::int64_t>(i) + 1;
    chapter->time_base = AVRational{1, 1000};
    chapter->start = milliseconds(mark.start_s);
    chapter->end = milliseconds(mark.end_s);
    av_dict_set(&chapter->metadata, "title", mark.title.c_str(), 0);
  }
}

}  // namespace systole::encode::detail
