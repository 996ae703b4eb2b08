#pragma once
// A small organ with the shipped heart's material (scenes/heart.yaml: 63 mg a particle,
// 400 N/m springs, 10 ms damping, a 3 kPa volume, 2/s drag) and its kind of motion: a
// pinned cap (the vessels), a narrow "atrium" band with a short, sharp contraction and a
// "ventricle" below it that follows 160 ms later. Stiff, strongly damped and partly pinned:
// the body on which the solvers used to disagree (docs/accuracy.md).

#include <utility>
#include <vector>

#include "mesh/geometry.h"
#include "sim/model.h"
#include "sim/motion_error.h"
#include "sim/solvers/step.h"
#include "support/shapes.h"

namespace systole::test {

struct SmallHeart {
  static constexpr double kRadius = 0.04;     ///< unit: m
  static constexpr double kBeatHz = 1.2;      ///< 72 bpm. unit: Hz
  static constexpr double kParticleKg = 6.3e-5;  ///< The shipped heart's mass per particle. unit: kg

  sim::OrganParams organ;
  mesh::OrganGeometry geometry;
  sim::ModelOptions options;

  explicit SmallHeart(int levels = 2) {
    const mesh::TriangleMesh surface = icosphere(kRadius, levels);
    std::vector<int> region(surface.positions.size(), -1);
    for (std::size_t i = 0; i < region.size(); ++i) {
      const double y = surface.positions[i].y() / kRadius;
      region[i] = y > 0.5 ? 2 : y >= 0 ? 0 : y < -0.2 ? 1 : -1;
    }
    geometry = geometry_of(surface, std::move(region));
    organ.name = "small heart";
    organ.body.mass_kg = kParticleKg * double(surface.positions.size());
    organ.body.stiffness_N_per_m = 400;
    organ.body.damping_s = 0.010;
    organ.body.volume_stiffness_Pa = 3000;
    organ.body.drag_per_s = 2;
    organ.regions = {band("atrium", 0.10, 0.15, 0.0), band("ventricle", 0.14, 0.36, 0.160), vessels()};
    options.clip_s = 10.0;
  }

  sim::Model model(sim::Method method, double dt_s, int substeps, int iterations = 2) const {
    sim::ModelOptions o = options;
    o.solver.method = method;
    o.solver.substeps = substeps;
    o.solver.iterations = iterations;
    o.dt_s = dt_s;
    return sim::build_model(organ, geometry, o);
  }

  /// The explicit solver at 1/60 s steps with the substeps its stability limit needs
  /// (solver.dt: auto's rule, sim/solvers/step_size.h), times `refine`.
  sim::Model explicit_reference(int refine = 1) const {
    sim::ModelOptions o = options;
    o.solver.method = sim::Method::kExplicit;
    o.solver.auto_substeps = true;
    o.dt_s = 1.0 / 60;
    const int substeps = sim::build_model(organ, geometry, o).substeps;
    return model(sim::Method::kExplicit, 1.0 / 60, refine * substeps);
  }

  /// Positions and each band's mean radial distance from the centre, sampled at 60 Hz over
  /// one beat after one beat of settling.
  struct Run {
    sim::Trajectory x;
    std::vector<std::vector<double>> band;  ///< Per driven region (atrium, ventricle).
  };
  Run run(const sim::Model& m, double dt_s) const {
    Run out;
    out.band.resize(2);
    std::vector<std::vector<int>> members(2);
    for (std::size_t v = 0; v < geometry.vertex_region.size(); ++v) {
      const int r = geometry.vertex_region[v];
      if (r == 0 || r == 1) members[r].push_back(static_cast<int>(v));
    }
    sim::State s = sim::initial_state(m);
    const int per_sample = static_cast<int>(std::lround((1.0 / 60) / dt_s));
    const int settle = 50, samples = 50;  // One beat each at 72 bpm and 60 Hz.
    for (int f = 1; f <= settle + samples; ++f) {
      for (int k = 0; k < per_sample; ++k) sim::step(m, s, dt_s);
      if (f <= settle) continue;
      out.x.push_back(s.x);
      for (int r = 0; r < 2; ++r) out.band[r].push_back(sim::mean_radial_distance_m(s.x, members[r], Eigen::Vector3d::Zero()));
    }
    return out;
  }

 private:
  static sim::RegionParams band(const char* name, double amplitude, double systolic_fraction, double delay_s) {
    sim::RegionParams r;
    r.name = name;
    r.drive.waveform = sim::Waveform::kCardiac;
    r.drive.rate_hz = kBeatHz;
    r.drive.amplitude = amplitude;
    r.drive.systolic_fraction = systolic_fraction;
    r.drive.delay_s = delay_s;
    return r;
  }
  static sim::RegionParams vessels() {
    sim::RegionParams r;
    r.name = "vessels";
    r.pinned = true;
    return r;
  }
};

}  // namespace systole::test
