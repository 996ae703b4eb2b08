// Cost of one simulation step per solver on organs of about 2.5k, 10k and 40k vertices
// (icospheres of a beating, volume-keeping body), in springs per second: compare with the
// machine's limit of a plain spring loop (bench/spring_loop_bench.cpp's figure); and one
// frame of the shipped heart (scenes/heart.yaml: the anatomical heart's myocardium, the
// scene's own solver), the simulate stage of its clip alone.
//
//   build/bench/sim_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>


#include "mesh/icosphere.h"
#include "scene/load.h"
#include "mesh/inspect.h"
#include "sim/model.h"
#include "sim/solvers/step.h"
#include "world/world.h"

namespace {

using namespace systole;

sim::Model beating_ball(int levels, sim::Method method, int substeps) {
  mesh::OrganGeometry g;
  g.mesh.surface = mesh::icosphere(0.05, levels);  // 10 * 4^levels + 2 particles.
  g.report = mesh::inspect(g.mesh.surface);
  g.vertex_region.resize(g.mesh.surface.positions.size());
  for (std::size_t i = 0; i < g.vertex_region.size(); ++i) g.vertex_region[i] = g.mesh.surface.positions[i].y() > 0 ? 0 : -1;
  sim::OrganParams organ;
  organ.name = "ball";
  organ.body.bending_N_per_m = 50;
  sim::RegionParams top;
  top.name = "top";
  top.drive.waveform = sim::Waveform::kCardiac;
  top.drive.rate_hz = 1.2;
  top.drive.amplitude = 0.12;
  organ.regions.push_back(top);
  sim::ModelOptions options;
  options.solver.method = method;
  options.solver.substeps = substeps;
  options.clip_s = 10;
  return sim::build_model(organ, g, options);
}

/// One step of 1/240 s; counters: springs solved per second, substeps per second.
void step_cost(benchmark::State& bench, sim::Method method, int substeps) {
  const sim::Model m = beating_ball(static_cast<int>(bench.range(0)), method, substeps);
  sim::State s = sim::initial_state(m);
  sim::step(m, s, 1.0 / 240);  // Warm: builds caches (the implicit pattern, the projective factors).
  sim::step(m, s, 1.0 / 240);
  for (auto _ : bench) {
    sim::step(m, s, 1.0 / 240);
    benchmark::DoNotOptimize(s.x.data());
  }
  const double substeps_done = double(bench.iterations()) * m.substeps;
  bench.counters["particles"] = m.particle_count();
  bench.counters["springs"] = m.springs.size();
  bench.counters["springs/s"] = benchmark::Counter(substeps_done * m.springs.size(), benchmark::Counter::kIsRate);
  bench.counters["substeps/s"] = benchmark::Counter(substeps_done, benchmark::Counter::kIsRate);
}

void Xpbd(benchmark::State& s) { step_cost(s, sim::Method::kXpbd, 4); }
void Explicit(benchmark::State& s) { step_cost(s, sim::Method::kExplicit, 4); }
void Implicit(benchmark::State& s) { step_cost(s, sim::Method::kImplicit, 1); }
void Projective(benchmark::State& s) { step_cost(s, sim::Method::kProjective, 1); }

// Levels 4, 5, 6: 2,562, 10,242 and 40,962 particles.
BENCHMARK(Xpbd)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(Explicit)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(Implicit)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(Projective)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

/// The machine's limit for this kind of work: a plain structure-of-arrays spring-force
/// loop (no constraint solve, no drive), the figure DESIGN.md quotes as ~170 M springs/s.
void SpringLoopLimit(benchmark::State& bench) {
  const sim::Model m = beating_ball(static_cast<int>(bench.range(0)), sim::Method::kExplicit, 1);
  const auto& sp = m.springs;
  const Eigen::Matrix3Xd x = m.rest_positions * 1.01;
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, x.cols());
  const double* px = x.data();
  double* pf = f.data();
  for (auto _ : bench) {
    for (int j = 0; j < sp.size(); ++j) {
      const int a = sp.a[j], b = sp.b[j];
      const double dx = px[3 * b] - px[3 * a], dy = px[3 * b + 1] - px[3 * a + 1], dz = px[3 * b + 2] - px[3 * a + 2];
      const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double t = (len - sp.rest_m[j]) / (sp.compliance_m_per_N[j] * len);
      pf[3 * a] += t * dx, pf[3 * a + 1] += t * dy, pf[3 * a + 2] += t * dz;
      pf[3 * b] -= t * dx, pf[3 * b + 1] -= t * dy, pf[3 * b + 2] -= t * dz;
    }
    benchmark::DoNotOptimize(pf);
  }
  bench.counters["springs/s"] = benchmark::Counter(double(bench.iterations()) * sp.size(), benchmark::Counter::kIsRate);
}
BENCHMARK(SpringLoopLimit)->DenseRange(4, 6)->Unit(benchmark::kMicrosecond);

/// One 1/30-s frame of scenes/heart.yaml's heart from one beat in (world::advance_to_frame:
/// its steps at the scene's dt and iterations, the health check, the valves): what
/// `systole render` reports as "simulate" for that clip, less the surface's normals, without
/// the other stages competing for the cores.
void ShippedHeartFrame(benchmark::State& bench) {
  world::World w = world::build_world(scene::load(SYSTOLE_SOURCE_DIR "/scenes/heart.yaml"));
  int frame = 30;
  world::advance_to_frame(w, frame);
  for (auto _ : bench) {
    world::advance_to_frame(w, ++frame);
    benchmark::DoNotOptimize(w.organs[0].state.x.data());
  }
  const sim::Model& heart = w.organs.at(0).model;
  bench.counters["particles"] = heart.particle_count();
  bench.counters["springs"] = heart.springs.size();
  bench.counters["steps/frame"] = w.steps_per_frame;
}
BENCHMARK(ShippedHeartFrame)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
