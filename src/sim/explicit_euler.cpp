#include "sim/explicit_euler.h"

#include <cmath>

#include "sim/drive.h"
#include "sim/forces.h"
#include "sim/interactions.h"

namespace systole::sim {

void explicit_step(const Model& model, State& s, double dt_s) {
  const int n = model.substeps;
  const double h = dt_s / n;
  const double drag = std::exp(-model.drag_per_s * h);
  const Eigen::Index count = s.x.cols();
  for (int sub = 0; sub < n; ++sub) {
    region_contractions(model.regions, model.beat_boundaries, s.time_s, model.ramp_s, s.region_contraction);
    internal_and_scripted_forces(model, s.x, s.v, s.time_s, s, s.force);
    for (Eigen::Index i = 0; i < count; ++i) {
      const double w = model.inverse_mass[i];
      if (w == 0) continue;
      s.v.col(i) = drag * (s.v.col(i) + h * (model.gravity + w * s.force.col(i)));
    }
    s.x_prev = s.x;
    s.x += h * s.v;
    move_kinematic_regions(model, s.time_s + h, s.x);
    if (model.floor.enabled) {
      resolve_floor_contact(model, s.x);
      s.v = (s.x - s.x_prev) / h;  // The contact removed the motion into the floor.
    }
    s.time_s += h;
  }
}

}  // namespace systole::sim
