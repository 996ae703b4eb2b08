#pragma once
// H.264 in MP4 that plays everywhere (DESIGN.md §4): High profile, yuv420p, limited
// range, BT.709 on the stream and in the RGB->YUV conversion, +faststart, exact pts and
// packet durations, encoder flushed. Written to a temporary file and renamed on finish().

#include <filesystem>
#include <memory>
#include <string>

#include "encode/frame_sink.h"

namespace systole::encode {

struct VideoSettings {
  int width = 1280;                 ///< unit: px; must be even.
  int height = 720;                 ///< unit: px; must be even.
  double fps = 30;                  ///< unit: frames/s; see frame_rate_of() for the exact rate.
  int crf = 20;                     ///< x264 constant rate factor, 0-51.
  std::string preset = "veryfast";  ///< x264 preset. "ultrafast" drops CABAC and the 8x8
                                    ///< transform, so the stream is Constrained Baseline (a
                                    ///< subset every High decoder plays); the others give High.
  int threads = 0;                  ///< Encoder threads; 0 lets x264 choose.
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

class Mp4Writer final : public FrameSink {
 public:
  /// Opens the encoder and a temporary file beside `target`. Throws Error(kDataError) for
  /// odd sizes or bad settings, Error(kCannotCreate) when the folder is missing or read-only,
  /// Error(kInternal) when libavcodec has no libx264 encoder.
  Mp4Writer(const std::filesystem::path& target, const VideoSettings& settings);
  /// Without finish(): frees everything and removes the temporary; `target` is untouched.
  ~Mp4Writer() override;
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  /// Encodes one frame (top row first, settings' size). The first frame's index may be any
  /// number (a --frames range); each next one must be exactly one more, because frame i of
  /// the video is shown at i / fps. Throws Error(kInternal) for a wrong size or index or
  /// after finish(), Error(kIoError) when writing fails.
  void write(const Image& image, int frame_index) override;
  /// Flushes the encoder, writes the trailer (moov moved before mdat) and renames the
  /// temporary to `target`. Throws Error(kInternal) when no frame was written.
  void finish() override;
  /// Frames written so far.
  int frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace systole::encode
