#pragma once
// Video files through libavcodec/libavformat, one class for every codec we write
// (docs/teaching-visuals.md, "Timing and formats"):
//  - MP4/H.264 that plays everywhere (DESIGN.md §4): High profile, yuv420p, limited range,
//    BT.709 on the stream and in the RGB->YUV conversion, +faststart;
//  - MKV/FFV1, the lossless archive: 8-bit RGB (bgr0), so the RGB frames come back bit for bit;
//  - WebM/VP9 for the web: yuv420p BT.709, constant quality, one thread, no row threading.
// Exact pts and packet durations, encoder flushed, bit-exact muxing (no random IDs or
// library versions in the file), so the same frames give the same bytes. Written to a
// temporary file and renamed on finish(). GIF has its own writer (encode/gif_writer.h).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "encode/frame_sink.h"

namespace systole::encode {

/// The containers and codecs `render` writes; the file's extension names one
/// (video_format_of).
enum class VideoFormat {
  kMp4,   ///< .mp4: H.264 (libx264), yuv420p. The default.
  kMkv,   ///< .mkv: FFV1 level 3, bgr0 (lossless 8-bit RGB), slice CRCs.
  kWebm,  ///< .webm: VP9 (libvpx-vp9), yuv420p, constant quality.
  kGif,   ///< .gif: 256 colours from one palette for the clip (encode/gif_writer.h).
};

/// The format an extension names (".mp4", ".mkv", ".webm", ".gif", any case); nullopt for
/// any other.
std::optional<VideoFormat> video_format_of(const std::filesystem::path& file);
/// "mp4", "mkv", "webm", "gif": the extension without the dot, and the scene's name for it.
const char* extension_of(VideoFormat format);

/// A subtitle cue: text shown over [from_s, to_s) of video time. unit: s
struct TextCue {
  double from_s = 0, to_s = 0;
  std::string text;  ///< UTF-8; "\n" breaks a line.
};

/// A chapter mark over [start_s, end_s) of video time. unit: s
struct ChapterMark {
  double start_s = 0, end_s = 0;
  std::string title;
};

struct VideoSettings {
  VideoFormat format = VideoFormat::kMp4;  ///< Not kGif: that is GifWriter's.
  int width = 1280;                 ///< unit: px; must be even.
  int height = 720;                 ///< unit: px; must be even.
  double fps = 30;                  ///< unit: frames/s; see frame_rate_of() for the exact rate.
  int crf = 20;                     ///< x264 constant rate factor, 0-51.
  std::string preset = "veryfast";  ///< x264 preset. "ultrafast" drops CABAC and the 8x8
                                    ///< transform, so the stream is Constrained Baseline (a
                                    ///< subset every High decoder plays); the others give High.
  int threads = 0;                  ///< Encoder threads; 0 lets x264 choose. FFV1 and VP9
                                    ///< always use 1: their output then never depends on it.
  int vp9_crf = 32;                 ///< VP9 constant quality, 0-63 (lower is better).
  int vp9_speed = 4;                ///< libvpx cpu-used, 0 (slowest, best) to 5, deadline "good".
  /// The soundtrack, mono, sample 0 at video time 0; empty: no sound. MP4 takes it as AAC
  /// (FFmpeg's own encoder), WebM as Opus (libopus), MKV as FLAC; the encoder's priming
  /// samples are declared (MP4 edit list, WebM CodecDelay) so sample 0 plays with frame 0.
  std::vector<float> audio;         ///< unit: full scale, in [-1, 1]
  int audio_rate_hz = 48000;        ///< unit: samples/s
  /// A subtitle track (MP4 mov_text, WebM WebVTT, MKV SubRip); empty: none.
  std::vector<TextCue> subtitles;
  /// Chapter marks (MP4 QuickTime and Nero chapters, Matroska and WebM Chapters).
  std::vector<ChapterMark> chapters;
};

/// An exact frame rate, num/den frames per second.
struct FrameRate {
  int num = 30;
  int den = 1;
};

/// The exact rate the video declares for `fps` (unit: frames/s): the NTSC rates 23.976,
/// 29.97, 59.94 (within 0.001) become 24000/1001, 30000/1001, 60000/1001; anything else is
/// the nearest fraction with a denominator up to 100000 (av_d2q). The stream's time base is
/// den/num s, so frame i starts at i * den / num s.
FrameRate frame_rate_of(double fps);

/// Opens the writer `settings.format` asks for: a VideoWriter, or a GifWriter for kGif
/// (which takes only the size and fps).
std::unique_ptr<FrameSink> open_video(const std::filesystem::path& target, const VideoSettings& settings);

class VideoWriter final : public FrameSink {
 public:
  /// Opens the encoder and a temporary file beside `target`. Throws Error(kDataError) for
  /// odd sizes or bad settings, Error(kCannotCreate) when the folder is missing or read-only,
  /// Error(kInternal) when libavcodec lacks the encoder (libx264, ffv1, libvpx-vp9).
  VideoWriter(const std::filesystem::path& target, const VideoSettings& settings);
  /// Without finish(): frees everything and removes the temporary; `target` is untouched.
  ~VideoWriter() override;
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Encodes one frame (top row first, settings' size). The first frame's index may be any
  /// number (a --frames range); each next one must be exactly one more, because frame i of
  /// the video is shown at i / fps. Throws Error(kInternal) for a wrong size or index or
  /// after finish(), Error(kIoError) when writing fails.
  void write(const Image& image, int frame_index) override;
  /// Flushes the encoder, writes the trailer (MP4: moov moved before mdat) and renames the
  /// temporary to `target`. Throws Error(kInternal) when no frame was written.
  void finish() override;
  /// Frames written so far.
  int frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace systole::encode
