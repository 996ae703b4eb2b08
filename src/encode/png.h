#pragma once
// PNG files (libpng): single images, written atomically, and numbered frame sequences,
// which replace the earlier frames of their folder only when the run completes.

#include <filesystem>
#include <string>

#include "common/folder_update.h"
#include "encode/frame_sink.h"

namespace systole::encode {

/// Writes an RGB PNG atomically (temporary + rename). Throws Error(kCannotCreate/kIoError);
/// a failed write says why (errno's text: "No space left on device").
void write_png(const std::filesystem::path& path, const Image& image);

/// Reads a PNG as 8-bit RGB (grey, palette, alpha and 16-bit are converted). Throws
/// Error(kNoInput) when missing, Error(kDataError) when it is not a readable PNG.
Image read_png(const std::filesystem::path& path);

/// Name of frame `index` in a sequence: frame_00042.png (at least 5 digits, more when
/// frame_count needs them), so names sort in frame order.
std::string frame_file_name(int index, int frame_count);

/// Writes frame i as <folder>/frame_file_name(i, frame_count). The frames go to a staging
/// folder first and replace their namesakes in <folder> (made if missing) only in finish(),
/// together (common/folder_update.h); the folder's other files, other frames included (a
/// --frames selection), stay as they were. Destroyed without finish() - an error, an
/// interrupt - it leaves the folder untouched. Holds the folder's lock while it lives
/// (joining the run's claim on this thread). Throws like FolderUpdate, and Error(kIoError)
/// naming the frame when one cannot be written.
class PngSequenceWriter final : public FrameSink {
 public:
  PngSequenceWriter(const std::filesystem::path& folder, int frame_count);
  /// Safe from another thread than the constructor's (the frame loop's encode stage).
  void write(const Image& image, int frame_index) override;
  void finish() override;

 private:
  FolderUpdate update_;
  int frame_count_;
};

}  // namespace systole::encode
