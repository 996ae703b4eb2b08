// Encoder costs at 720p (docs/performance.md): each video format, the H.264 presets, PNG
// frames written and read back. These were disabled "Speed" tests in tests/encode/ before.
//
// Frames are a shaded disc that drifts and pulses over a vignette, forward then backward:
// continuous motion, so inter-frame coding costs what it does on a rendered organ.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "common/image.h"
#include "encode/png.h"
#include "encode/video_writer.h"

namespace {

using namespace systole;
namespace fs = std::filesystem;

constexpr int kWidth = 1280, kHeight = 720;  // unit: px

/// Frame `index` of a 30-frame cycle.
Image moving_disc(int index) {
  Image image(kWidth, kHeight);
  const double phase = 2 * M_PI * index / 30.0;
  const double cx = kWidth * (0.5 + 0.05 * std::sin(phase * 0.5)), cy = kHeight * 0.5;
  const double radius = kHeight * (0.33 + 0.03 * std::sin(phase));
  for (int y = 0; y < kHeight; ++y) {
    std::uint8_t* row = image.row(y);
    for (int x = 0; x < kWidth; ++x) {
      const double dx = (x - cx) / radius, dy = (y - cy) / (radius * 1.2);
      const double d2 = dx * dx + dy * dy;
      const double shade = d2 < 1 ? 40 + 170 * std::max(0.0, -0.4 * dx - 0.5 * dy + 0.77 * std::sqrt(1 - d2)) : 30;
      row[3 * x + 0] = static_cast<std::uint8_t>(std::min(255.0, shade));
      row[3 * x + 1] = static_cast<std::uint8_t>(std::min(255.0, 0.4 * shade));
      row[3 * x + 2] = static_cast<std::uint8_t>(std::min(255.0, 0.35 * shade + 10));
    }
  }
  return image;
}

const std::vector<Image>& cycle() {
  static const std::vector<Image> frames = [] {
    std::vector<Image> f;
    for (int i = 0; i < 30; ++i) f.push_back(moving_disc(i));
    return f;
  }();
  return frames;
}

/// Forward then backward through the cycle.
const Image& frame(int i) {
  const int n = static_cast<int>(cycle().size());
  const int k = i % (2 * n);
  return cycle()[static_cast<std::size_t>(k < n ? k : 2 * n - 1 - k)];
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "systole_encode_bench" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// 90 frames of one format (0 mp4, 1 mkv, 2 webm, 3 gif); time per frame.
void BM_EncodeFormat720p(benchmark::State& state) {
  const char* ext = std::array{"mp4", "mkv", "webm", "gif"}[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(ext);
  encode::VideoSettings s;
  s.format = *encode::video_format_of(std::string("x.") + ext);
  s.width = kWidth, s.height = kHeight, s.fps = 25, s.threads = 1;
  const fs::path file = scratch(ext) / (std::string("clip.") + ext);
  constexpr int kCount = 90;
  for (auto _ : state) {
    auto sink = encode::open_video(file, s);
    for (int i = 0; i < kCount; ++i) sink->write(frame(i), i);
    sink->finish();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
  state.counters["kB_per_frame"] = static_cast<double>(fs::file_size(file)) / 1e3 / kCount;
}
BENCHMARK(BM_EncodeFormat720p)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

/// 240 H.264 frames at crf 20 with 2 threads, per preset (0 veryfast, 1 ultrafast, 2 superfast, 3 medium).
void BM_EncodeH264Preset720p(benchmark::State& state) {
  const char* preset = std::array{"veryfast", "ultrafast", "superfast", "medium"}[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(preset);
  encode::VideoSettings s;
  s.preset = preset;
  s.crf = 20;
  s.threads = 2;
  const fs::path file = scratch(preset) / "clip.mp4";
  constexpr int kCount = 240;
  for (auto _ : state) {
    encode::VideoWriter writer(file, s);
    for (int i = 0; i < kCount; ++i) writer.write(frame(i), i);
    writer.finish();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
  state.counters["kB_per_frame"] = static_cast<double>(fs::file_size(file)) / 1e3 / kCount;
}
BENCHMARK(BM_EncodeH264Preset720p)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_WritePng720p(benchmark::State& state) {
  const fs::path dir = scratch("png_write");
  encode::PngSequenceWriter writer(dir, 1 << 20);
  int i = 0;
  for (auto _ : state) writer.write(frame(0), i++);
}
BENCHMARK(BM_WritePng720p)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReadPng720p(benchmark::State& state) {
  const fs::path dir = scratch("png_read");
  encode::PngSequenceWriter writer(dir, 1);
  writer.write(frame(0), 0);
  writer.finish();
  const fs::path file = dir / encode::frame_file_name(0, 1);
  for (auto _ : state) benchmark::DoNotOptimize(encode::read_png(file));
}
BENCHMARK(BM_ReadPng720p)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
