#pragma once
// PNG files (libpng): single images, written atomically, and numbered frame sequences.

#include <filesystem>
#include <string>

#include "encode/frame_sink.h"

namespace systole::encode {

/// Writes an RGB PNG atomically (temporary + rename). Throws Error(kCannotCreate/kIoError).
void write_png(const std::filesystem::path& path, const Image& image);

/// Reads a PNG as 8-bit RGB (grey, palette, alpha and 16-bit are converted). Throws
/// Error(kNoInput) when missing, Error(kDataError) when it is not a readable PNG.
Image read_png(const std::filesystem::path& path);

/// Name of frame `index` in a sequence: frame_00042.png (at least 5 digits, more when
/// frame_count needs them), so names sort in frame order.
std::string frame_file_name(int index, int frame_count);

/// Writes each frame as <folder>/frame_NNNNN.png; creates the folder if missing.
class PngSequenceWriter final : public FrameSink {
 public:
  PngSequenceWriter(const std::filesystem::path& folder, int frame_count);
  void write(const Image& image, int frame_index) override;
  void finish() override {}

 private:
  std::filesystem::path folder_;
  int frame_count_;
};

}  // namespace systole::encode
