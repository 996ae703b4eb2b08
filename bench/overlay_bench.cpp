// Cost of the teaching overlays per frame (app/overlay_plan.h) at 1280x720 with
// scenes/heart-labels.yaml's set: 7 labels, a 9-entry legend, two 360x110 trace insets
// (ECG and volume) and a title. Capture (anchors from positions) and draw are timed
// apart; draw runs on an image already holding a frame, as in a render, and takes the
// frame time along the clip so the traces and label placement change every iteration.

#include <benchmark/benchmark.h>

#include <string>

#include "clip/overlay_plan.h"
#include "scene/load.h"
#include "world/world.h"

namespace {

using namespace systole;

struct Fixture {
  scene::Scene scene = scene::load(std::string(SYSTOLE_SOURCE_DIR) + "/scenes/heart-labels.yaml");
  world::World world = world::build_world(scene);
  clip::OverlayPlan plan{scene, world};
  Eigen::Matrix3Xd x;
  std::vector<const Eigen::Matrix3Xd*> positions{&x};

  Fixture() {
    world::render_positions(world.organs[0], x);
    for (int f = 0; f < scene.output.frame_count(); ++f) plan.record_volume(0, f, x);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void BM_OverlayCapture(benchmark::State& state) {
  auto& f = fixture();
  clip::OverlayFrame frame;
  int i = 0;
  for (auto _ : state) {
    f.plan.capture(i++ % f.scene.output.frame_count(), f.positions, frame);
    benchmark::DoNotOptimize(frame.labels.data());
  }
}
BENCHMARK(BM_OverlayCapture)->Unit(benchmark::kMillisecond);

void BM_OverlayDraw720p(benchmark::State& state) {
  auto& f = fixture();
  Image base(f.scene.output.width, f.scene.output.height);
  for (std::size_t k = 0; k < base.rgb.size(); ++k) base.rgb[k] = static_cast<std::uint8_t>(20 + k % 7);
  Image image = base;
  std::vector<clip::OverlayFrame> frames(static_cast<std::size_t>(f.scene.output.frame_count()));
  for (std::size_t k = 0; k < frames.size(); ++k) f.plan.capture(static_cast<int>(k), f.positions, frames[k]);
  f.plan.draw(image, frames[0]);  // Loads the font and lays out once, as the first frame of a clip does.
  std::size_t k = 0;
  for (auto _ : state) {
    state.PauseTiming();
    image.rgb = base.rgb;
    state.ResumeTiming();
    f.plan.draw(image, frames[k++ % frames.size()]);
    benchmark::DoNotOptimize(image.rgb.data());
  }
}
BENCHMARK(BM_OverlayDraw720p)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
