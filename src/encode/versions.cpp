#include "encode/versions.h"

#include <png.h>

#include <algorithm>
#include <utility>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libswscale/swscale.h>
}

namespace systole::encode {
namespace {

std::string version_line(const char* name, unsigned version) {
  return std::string(name) + " " + std::to_string(AV_VERSION_MAJOR(version)) + "." +
         std::to_string(AV_VERSION_MINOR(version)) + "." + std::to_string(AV_VERSION_MICRO(version));
}

}  // namespace

std::vector<std::string> library_versions() {
  // Run-time versions (the shared libraries actually loaded), not the headers'.
  return {version_line("libavcodec", avcodec_version()), version_line("libavformat", avformat_version()),
          version_line("libavutil", avutil_version()), version_line("libswscale", swscale_version()),
          std::string("libpng ") + png_get_libpng_ver(nullptr)};
}

std::vector<std::string> h264_encoders() {
  std::vector<std::string> names;
  void* opaque = nullptr;
  while (const AVCodec* codec = av_codec_iterate(&opaque)) {
    if (codec->id == AV_CODEC_ID_H264 && av_codec_is_encoder(codec)) names.emplace_back(codec->name);
  }
  // libx264 first (it is what VideoWriter uses), the others in libavcodec's order.
  std::stable_partition(names.begin(), names.end(), [](const std::string& n) { return n == "libx264"; });
  return names;
}

std::vector<std::string> output_formats() {
  std::vector<std::string> lines;
  for (const auto& [format, encoder] : {std::pair{"mp4", "libx264"}, std::pair{"mkv", "ffv1"},
                                        std::pair{"webm", "libvpx-vp9"}, std::pair{"gif", "gif"}}) {
    const bool present = avcodec_find_encoder_by_name(encoder) != nullptr;
    lines.push_back(std::string(format) + " (" + encoder + (present ? ")" : ": missing)"));
  }
  return lines;
}

}  // namespace systole::encode
