// Cost of render::Renderer at video size: draw (rasterize + shade, glFinish'ed) and
// read_frame (MSAA resolve + glReadPixels + row flip), for a ~20k-triangle sphere that
// fills about a fifth of a 1280x720 frame, and the CPU FXAA pass that replaces 4x MSAA.
// Run with LP_NUM_THREADS=2 (or 1) to compare; LP_NUM_THREADS=0 rasterizes on the calling
// thread, so the CPU column is the whole cost whatever else the machine runs.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "render/fxaa.h"
#include "render/renderer.h"

namespace {

using systole::render::Renderer;

struct Sphere {
  std::vector<float> positions, normals;
  std::vector<Eigen::Vector3i> triangles;
};

/// UV sphere of radius 0.1 m: 2 * 100 * 99 = 19800 triangles.
Sphere make_sphere() {
  constexpr int kStacks = 100, kSlices = 100;
  Sphere s;
  for (int i = 0; i <= kStacks; ++i) {
    const double theta = std::numbers::pi * i / kStacks;
    for (int j = 0; j <= kSlices; ++j) {
      const double phi = 2 * std::numbers::pi * j / kSlices;
      const float n[3] = {static_cast<float>(std::sin(theta) * std::cos(phi)),
                          static_cast<float>(std::cos(theta)),
                          static_cast<float>(-std::sin(theta) * std::sin(phi))};
      for (float c : n) s.normals.push_back(c), s.positions.push_back(0.1f * c);
    }
  }
  for (int i = 0; i < kStacks; ++i) {
    for (int j = 0; j < kSlices; ++j) {
      const int a = i * (kSlices + 1) + j, b = a + kSlices + 1, c = b + 1, d = a + 1;
      if (i != 0) s.triangles.emplace_back(a, b, d);
      if (i != kStacks - 1) s.triangles.emplace_back(b, c, d);
    }
  }
  return s;
}

struct Fixture {
  Sphere sphere = make_sphere();
  Renderer renderer;
  systole::scene::Camera camera;
  std::vector<systole::scene::Light> lights{systole::scene::Light{}};
  systole::scene::Color background{0.06, 0.07, 0.09};
  int id = 0;

  explicit Fixture(int msaa) : renderer(1280, 720, msaa) {
    const std::vector<systole::scene::Color> colors(sphere.positions.size() / 3,
                                                    systole::scene::Material{}.color);
    id = renderer.add_surface(sphere.triangles, colors, systole::scene::Material{});
    renderer.update_surface(id, sphere.positions.data(), sphere.normals.data());
  }
};

void BM_Draw(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(static_cast<int>(state.range(0)));
  f.renderer.draw(f.camera, f.lights, f.background);  // Links the program for this light count.
  for (auto _ : state) f.renderer.draw(f.camera, f.lights, f.background);
  state.counters["triangles"] = static_cast<double>(f.sphere.triangles.size());
}

void BM_ReadFrame(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(static_cast<int>(state.range(0)));
  f.renderer.draw(f.camera, f.lights, f.background);
  systole::Image image;
  for (auto _ : state) f.renderer.read_frame(image);
}

/// The FXAA pass (render/fxaa.h) on the frame without MSAA: the alternative to BM_*/4.
void BM_Fxaa(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(0);
  f.renderer.draw(f.camera, f.lights, f.background);
  systole::Image frame, image;
  f.renderer.read_frame(frame);
  systole::render::Fxaa fxaa;
  for (auto _ : state) {
    state.PauseTiming();
    image = frame;
    state.ResumeTiming();
    fxaa.apply(image);
  }
}

void BM_UpdateSurface(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(0);
  for (auto _ : state) f.renderer.update_surface(f.id, f.sphere.positions.data(), f.sphere.normals.data());
}

BENCHMARK(BM_Draw)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReadFrame)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Fxaa)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_UpdateSurface)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
