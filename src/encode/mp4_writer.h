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
  double fps = 30;                  ///< unit: frames/s
  int crf = 20;                     ///< x264 constant rate factor, 0-51.
  std::string preset = "veryfast";  ///< x264 preset.
  int threads = 0;                  ///< Encoder threads; 0 lets x264 choose.
};

class Mp4Writer final : public FrameSink {
 public:
  /// Opens the encoder and a temporary file beside `target`. Throws Error(kDataError) for
  /// odd sizes or bad settings, Error(kCannotCreate) when the folder is missing or read-only.
  Mp4Writer(const std::filesystem::path& target, const VideoSettings& settings);
  ~Mp4Writer() override;

  void write(const Image& image, int frame_index) override;
  void finish() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace systole::encode
