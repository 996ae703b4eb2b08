#pragma once
// Helpers for the encode/ tests: a scratch folder per test, ffprobe, MP4 box order and
// a libavcodec decoder that returns the raw YUV planes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/image.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace systole::encode::test {

namespace fs = std::filesystem;

/// An empty folder for the running test: <SYSTOLE_TEST_SCRATCH>/<suite>.<test>.
inline fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(SYSTOLE_TEST_SCRATCH) / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

/// Runs a shell command and returns its standard output.
inline std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  ::pclose(pipe);
  return out;
}

/// ffprobe's JSON for the file's streams and format, frames counted.
inline std::string ffprobe_json(const fs::path& file) {
  return run("ffprobe -v error -count_frames -show_streams -show_format -of json '" + file.string() + "'");
}

/// The value of the first `"key": value` at or after `from` in flat JSON text, quotes removed.
inline std::string json_value(const std::string& json, const std::string& key, const std::string& from = "") {
  std::size_t start = from.empty() ? 0 : json.find("\"" + from + "\"");
  if (start == std::string::npos) return "<no " + from + ">";
  const std::size_t k = json.find("\"" + key + "\":", start);
  if (k == std::string::npos) return "<no " + key + ">";
  std::size_t v = json.find_first_not_of(" ", k + key.size() + 3);
  if (json[v] == '"') return json.substr(v + 1, json.find('"', v + 1) - v - 1);
  return json.substr(v, json.find_first_of(",\n}", v) - v);
}

/// Types of the top-level MP4 boxes in file order ("ftyp", "moov", "mdat", ...).
inline std::vector<std::string> top_level_boxes(const fs::path& file) {
  const std::string bytes = read_bytes(file);
  std::vector<std::string> types;
  std::size_t pos = 0;
  while (pos + 8 <= bytes.size()) {
    auto byte = [&](std::size_t i) { return static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i])); };
    std::uint64_t size = byte(pos) << 24 | byte(pos + 1) << 16 | byte(pos + 2) << 8 | byte(pos + 3);
    types.push_back(bytes.substr(pos + 4, 4));
    if (size == 1) {  // 64-bit size follows the type.
      if (pos + 16 > bytes.size()) break;
      size = 0;
      for (int i = 0; i < 8; ++i) size = size << 8 | byte(pos + 8 + static_cast<std::size_t>(i));
    } else if (size == 0) {  // Box runs to the end of the file.
      size = bytes.size() - pos;
    }
    if (size < 8) {
      types.push_back("<bad size>");
      break;
    }
    pos += size;
  }
  return types;
}

/// One decoded frame: 8-bit Y, U, V planes (U, V at half size).
struct YuvFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> y, u, v;
  int Y(int px, int py) const { return y[static_cast<std::size_t>(py) * width + px]; }
  int U(int px, int py) const { return u[static_cast<std::size_t>(py / 2) * (width / 2) + px / 2]; }
  int V(int px, int py) const { return v[static_cast<std::size_t>(py / 2) * (width / 2) + px / 2]; }
};

/// Calls `take` with every decoded frame of the file's first video stream, in order.
inline void for_each_decoded_frame(const fs::path& file, const std::function<void(const AVFrame&)>& take) {
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, file.c_str(), nullptr, nullptr) < 0) return;
  avformat_find_stream_info(fmt, nullptr);
  const AVCodec* codec = nullptr;
  const int index = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  AVCodecContext* dec = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(dec, fmt->streams[index]->codecpar);
  avcodec_open2(dec, codec, nullptr);
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto drain = [&] {
    while (avcodec_receive_frame(dec, frame) == 0) {
      take(*frame);
      av_frame_unref(frame);
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == index) {
      avcodec_send_packet(dec, pkt);
      drain();
    }
    av_packet_unref(pkt);
  }
  avcodec_send_packet(dec, nullptr);
  drain();
  av_frame_free(&frame);
  av_packet_free(&pkt);
  avcodec_free_context(&dec);
  avformat_close_input(&fmt);
}

/// Decodes every frame of the file's first video stream with libavcodec (yuv420p only).
inline std::vector<YuvFrame> decode_all(const fs::path& file) {
  std::vector<YuvFrame> frames;
  for_each_decoded_frame(file, [&](const AVFrame& frame) {
    YuvFrame f;
    f.width = frame.width;
    f.height = frame.height;
    for (int plane = 0; plane < 3; ++plane) {
      const int w = plane == 0 ? f.width : f.width / 2, h = plane == 0 ? f.height : f.height / 2;
      auto& out = plane == 0 ? f.y : plane == 1 ? f.u : f.v;
      for (int row = 0; row < h; ++row) {
        const std::uint8_t* src = frame.data[plane] + static_cast<std::ptrdiff_t>(row) * frame.linesize[plane];
        out.insert(out.end(), src, src + w);
      }
    }
    frames.push_back(std::move(f));
  });
  return frames;
}

/// Decodes every frame of the file's video stream into RGB24: BT.709 limited-range YUV
/// through swscale's exact-rounding path, RGB (bgr0, planar GBR) and PAL8 by copying values.
inline std::vector<Image> decode_rgb(const fs::path& file) {
  std::vector<Image> frames;
  for_each_decoded_frame(file, [&](const AVFrame& frame) {
    Image rgb(frame.width, frame.height);
    const auto f = static_cast<AVPixelFormat>(frame.format);
    if (f == AV_PIX_FMT_GBRP) {
      for (int y = 0; y < rgb.height; ++y)
        for (int x = 0; x < rgb.width; ++x) {
          auto at = [&](int plane) { return frame.data[plane][static_cast<std::ptrdiff_t>(y) * frame.linesize[plane] + x]; };
          std::uint8_t* p = rgb.row(y) + 3 * x;
          p[0] = at(2), p[1] = at(0), p[2] = at(1);  // GBRP planes: G, B, R.
        }
    } else {
      const bool copy = f == AV_PIX_FMT_PAL8 || f == AV_PIX_FMT_BGR0 || f == AV_PIX_FMT_BGRA || f == AV_PIX_FMT_RGB24 ||
                        f == AV_PIX_FMT_RGBA;
      SwsContext* sws = sws_getContext(rgb.width, rgb.height, f, rgb.width, rgb.height, AV_PIX_FMT_RGB24,
                                       copy ? SWS_POINT : SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                                       nullptr, nullptr);
      if (!copy) {
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      }
      std::uint8_t* dst[1] = {rgb.rgb.data()};
      const int stride[1] = {rgb.width * 3};
      sws_scale(sws, frame.data, frame.linesize, 0, rgb.height, dst, stride);
      sws_freeContext(sws);
    }
    frames.push_back(std::move(rgb));
  });
  return frames;
}

/// A shaded, pulsing blob on a dark vignette with a little texture: like a rendered organ.
inline Image organ_frame(int width, int height, int index) {
  Image image(width, height);
  const double phase = 2 * M_PI * index / 30.0;
  const double cx = width * (0.5 + 0.05 * std::sin(phase * 0.5)), cy = height * 0.5;
  const double radius = height * (0.33 + 0.03 * std::sin(phase));
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = image.row(y);
    for (int x = 0; x < width; ++x) {
      const double dx = (x - cx) / radius, dy = (y - cy) / (radius * 1.2);
      const double d2 = dx * dx + dy * dy;
      const double vignette = 40 * (1 - 0.5 * ((x - width / 2.0) * (x - width / 2.0) + (y - height / 2.0) * (y - height / 2.0)) /
                                            (width * width / 4.0));
      double r = vignette * 0.6, g = vignette * 0.7, b = vignette;
      if (d2 < 1) {
        const double nz = std::sqrt(1 - d2);
        const double diffuse = std::max(0.0, -0.4 * dx - 0.5 * dy + 0.77 * nz);
        const double spec = std::pow(std::max(0.0, 0.3 * -dx + 0.3 * -dy + 0.9 * nz), 40);
        const double vein = 0.5 + 0.5 * std::sin(dx * 23 + std::sin(dy * 7 + phase) * 3);
        r = 40 + 170 * diffuse * (0.9 + 0.1 * vein) + 200 * spec;
        g = 15 + 60 * diffuse * (0.8 + 0.2 * vein) + 200 * spec;
        b = 20 + 55 * diffuse + 200 * spec;
      }
      row[3 * x + 0] = static_cast<std::uint8_t>(std::min(255.0, r));
      row[3 * x + 1] = static_cast<std::uint8_t>(std::min(255.0, g));
      row[3 * x + 2] = static_cast<std::uint8_t>(std::min(255.0, b));
    }
  }
  return image;
}

}  // namespace systole::encode::test
