#pragma once
// Animated GIF for slides: one palette for the whole clip (encode/palette.h), ordered
// dither, looping forever, frame delays in exact centiseconds (their sum is the clip's
// length to within 1 cs). A palette for the whole clip needs every frame before the first
// can be written, so frames are kept in an unlinked temporary file until finish().
// Written to a temporary file beside the target and renamed on finish().

#include <filesystem>
#include <memory>

#include "encode/frame_sink.h"

namespace systole::encode {

struct GifSettings {
  int width = 480;   ///< unit: px
  int height = 270;  ///< unit: px
  double fps = 25;   ///< unit: frames/s; at most 50 (browsers show faster GIFs at 10 fps).
};

class GifWriter final : public FrameSink {
 public:
  /// Throws Error(kDataError) for a bad size or fps, Error(kCannotCreate) when the target's
  /// folder is missing or read-only.
  GifWriter(const std::filesystem::path& target, const GifSettings& settings);
  ~GifWriter() override;
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Keeps the frame (consecutive indices from any first one, as VideoWriter).
  void write(const Image& image, int frame_index) override;
  /// Builds the palette, encodes every frame and renames the file into place.
  void finish() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace systole::encode
