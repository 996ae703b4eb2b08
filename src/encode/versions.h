#pragma once
// What `systole info` reports about the encoding libraries.

#include <string>
#include <vector>

namespace systole::encode {

/// "libavcodec 59.37.100", ... for each FFmpeg library linked (run-time versions), then
/// "libpng 1.6.39".
std::vector<std::string> library_versions();

/// Names of the H.264 encoders libavcodec offers (libx264 first when present).
std::vector<std::string> h264_encoders();

/// "mp4 (libx264)", "mkv (ffv1)", "webm (libvpx-vp9)", "gif (gif)": the formats `render`
/// writes and their encoders, "...: missing)" when this libavcodec lacks one.
std::vector<std::string> output_formats();

}  // namespace systole::encode
