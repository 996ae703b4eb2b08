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

#include "mesh/strain.h"
#include "render/color_map.h"
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

/// Teaching visuals (docs/teaching-visuals.md): the sphere inside a second one 1.3 times its
/// size, the outer at opacity range(0) / 100. 100 draws both opaque (the outer hides the
/// inner); below 100 the outer goes through weighted blended OIT (accumulation pass into
/// RGBA16F + R16F, then a full-frame composite): the difference is what transparency costs.
void BM_DrawNested(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(0);
  std::vector<float> outer = f.sphere.positions;
  for (float& c : outer) c *= 1.3f;
  systole::scene::Material material;
  material.opacity = static_cast<double>(state.range(0)) / 100;
  const std::vector<systole::scene::Color> white(outer.size() / 3, systole::scene::Color(0.9, 0.9, 0.9));
  const int id = f.renderer.add_surface(f.sphere.triangles, white, material);
  f.renderer.update_surface(id, outer.data(), f.sphere.normals.data());
  f.renderer.draw(f.camera, f.lights, f.background);  // Links the programs, makes the OIT targets.
  for (auto _ : state) f.renderer.draw(f.camera, f.lights, f.background);
}

/// The sphere cut in half by a clip plane facing the camera (culling off, the inside shaded).
void BM_DrawClipped(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(0);
  systole::scene::ClipPlane clip;
  clip.enabled = true;
  clip.normal = Eigen::Vector3d(0, 0, -1);
  f.renderer.set_clip(f.id, clip);
  f.renderer.draw(f.camera, f.lights, f.background);
  for (auto _ : state) f.renderer.draw(f.camera, f.lights, f.background);
}

/// Strain colouring per frame on the CPU: per-vertex strain from the positions, the colour
/// map, and the upload (10 201 vertices, 29 900 edges).
void BM_StrainColors(benchmark::State& state) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Fixture f(0);
  const std::size_t n = f.sphere.positions.size() / 3;
  std::vector<Eigen::Vector3d> rest(n);
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(n));
  for (std::size_t v = 0; v < n; ++v) {
    rest[v] = Eigen::Vector3d(f.sphere.positions[3 * v], f.sphere.positions[3 * v + 1], f.sphere.positions[3 * v + 2]);
    x.col(static_cast<Eigen::Index>(v)) = rest[v] * (1 - 0.1 * (rest[v].y() + 0.1));
  }
  const systole::mesh::VertexStrain strain(rest, f.sphere.triangles);
  const systole::render::ColorMap map;
  std::vector<double> values;
  std::vector<float> colors(3 * n);
  for (auto _ : state) {
    strain.compute(x, values);
    for (std::size_t v = 0; v < n; ++v) {
      const systole::scene::Color c = map.at(values[v]);
      for (int k = 0; k < 3; ++k) colors[3 * v + k] = static_cast<float>(c[k]);
    }
    f.renderer.update_colors(f.id, colors.data());
  }
}

BENCHMARK(BM_DrawNested)->Arg(100)->Arg(50)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DrawClipped)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StrainColors)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_Draw)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReadFrame)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Fxaa)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_UpdateSurface)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
