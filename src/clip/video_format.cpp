#include "clip/video_format.h"

#include <utility>

#include "common/error.h"

namespace systole::clip {
namespace {

/// Encoder threads, for the two-core machines we target (docs/performance.md): x264 on one
/// thread beside the simulation and the rasterizer (batch/batch.h: rasterizer_threads).
constexpr int kEncoderThreads = 1;

encode::VideoFormat encode_format(scene::Format f) {
  switch (f) {
    case scene::Format::kMkv: return encode::VideoFormat::kMkv;
    case scene::Format::kWebm: return encode::VideoFormat::kWebm;
    case scene::Format::kGif: return encode::VideoFormat::kGif;
    default: return encode::VideoFormat::kMp4;
  }
}

}  // namespace

std::filesystem::path default_video_path(const scene::Scene& scene) {
  if (!scene.output.file.empty()) return scene.output.file;
  return std::filesystem::path("out") / (scene.name + "." + encode::extension_of(encode_format(scene.output.format)));
}

encode::VideoFormat video_format(const scene::Scene& scene, const std::filesystem::path& video) {
  if (const auto named = encode::video_format_of(video)) return *named;
  if (video.has_extension()) {
    throw Error(ExitCode::kUsage, video.string() + ": '" + video.extension().string() +
                                      "' is not a video's extension; name the output .mp4, .mkv, .webm or .gif, or "
                                      "give it no extension to take output.format's");
  }
  return encode_format(scene.output.format);
}

encode::VideoSettings video_settings(const scene::Output& out, encode::VideoFormat format) {
  encode::VideoSettings v;
  v.format = format;
  v.width = out.width;
  v.height = out.height;
  v.fps = out.fps;
  v.crf = out.crf;
  v.preset = out.preset;
  v.threads = kEncoderThreads;
  const auto [vp9_crf, vp9_speed] = out.quality == scene::Quality::kDraft      ? std::pair{40, 5}
                                    : out.quality == scene::Quality::kArchival ? std::pair{24, 2}
                                                                               : std::pair{32, 4};
  v.vp9_crf = vp9_crf;
  v.vp9_speed = vp9_speed;
  return v;
}

}  // namespace systole::clip
