#pragma once
// The simulator's test body, written once: a sphere whose upper half (y > 0) is one driven
// region, "top", with the default body otherwise. Each test changes what it is about
// (stiffness, damping, solver, drive) and builds the model.

#include <utility>
#include <vector>

#include "mesh/geometry.h"
#include "sim/model.h"
#include "support/shapes.h"

namespace systole::test {

struct BeatingBall {
  sim::OrganParams organ;
  mesh::OrganGeometry geometry;
  sim::ModelOptions options;
  double radius_m;

  /// A sphere of radius_m meshed at icosphere `levels`, its top half driven by a sine at
  /// rate_hz with `amplitude`; clip 10 s.
  explicit BeatingBall(int levels = 3, double rate_hz = 1.5, double amplitude = 0.15, double radius_m = 0.05)
      : radius_m(radius_m) {
    set_surface(icosphere(radius_m, levels));
    organ.name = "ball";
    sim::RegionParams top;
    top.name = "top";
    top.drive.waveform = sim::Waveform::kSine;
    top.drive.rate_hz = rate_hz;
    top.drive.amplitude = amplitude;
    organ.regions.push_back(top);
    options.clip_s = 10.0;
  }

  sim::RegionParams& top() { return organ.regions.front(); }

  /// Another surface (an edited or broken one) with the same rule for the driven top half,
  /// inspected again as the pipeline does.
  void set_surface(const mesh::TriangleMesh& surface) {
    std::vector<int> region(surface.positions.size(), -1);
    for (std::size_t i = 0; i < region.size(); ++i) region[i] = surface.positions[i].y() > 0 ? 0 : -1;
    geometry = geometry_of(surface, std::move(region));
  }

  /// Pins a cap at the bottom, the vertices below -below_fraction * radius, as a region
  /// "base" (as vessels hold a heart, so a push dents the body instead of moving it).
  void pin_base(double below_fraction) {
    std::vector<int>& region = geometry.vertex_region;
    for (std::size_t i = 0; i < region.size(); ++i) {
      if (geometry.mesh.surface.positions[i].y() < -below_fraction * radius_m) region[i] = 1;
    }
    sim::RegionParams base;
    base.name = "base";
    base.pinned = true;
    organ.regions.push_back(base);
  }
  sim::Model model() const { return sim::build_model(organ, geometry, options); }
};

}  // namespace systole::test
