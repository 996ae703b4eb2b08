#pragma once
// The text a video file carries beside its pictures: the captions as a subtitle stream and
// the chapter marks (internal to video_writer.cpp; not part of the API).

#include <string>
#include <vector>

#include "encode/video_writer.h"

struct AVFormatContext;
struct AVPacket;
struct AVStream;

namespace systole::encode::detail {

/// The captions, encoded up front by `encoder` (one that takes ASS dialogue lines:
/// mov_text, webvtt, ass) into a stream of `format` with a 1-ms time base, language "eng".
/// Make it before the header is written, write() it after. Errors throw Error with
/// "<label> encoder: ..." (kInternal for a missing encoder or a refused cue).
class SubtitleStream {
 public:
  SubtitleStream(AVFormatContext* format, const char* encoder, const std::vector<TextCue>& cues, std::string label);
  ~SubtitleStream();
  SubtitleStream(const SubtitleStream&) = delete;
  SubtitleStream& operator=(const SubtitleStream&) = delete;

  /// Every cue at once: the muxer's interleaving queue holds each until the frames reach
  /// it. Throws Error(kIoError) when a packet cannot be written.
  void write(AVFormatContext* format);

 private:
  AVStream* stream_ = nullptr;      // Owned by the format context.
  std::vector<AVPacket*> packets_;  // Encoded, not yet written.
  std::string label_;
};

/// The chapter marks into `format` (1-ms time base, each titled), freed with it. Throws
/// Error(kInternal) "<label> encoder: out of memory".
void add_chapters(AVFormatContext* format, const std::vector<ChapterMark>& chapters, const std::string& label);

}  // namespace systole::encode::detail
