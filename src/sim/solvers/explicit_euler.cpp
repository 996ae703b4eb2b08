#include "sim/solvers/explicit_euler.h"

#include <cmath>

#include "sim/forces.h"
#include "sim/solvers/substep.h"

namespace systole::sim {

void explicit_step(const Model& model, State& s, double dt_s) {
  const int n = model.substeps;
  const double h = dt_s / n;
  const double drag = std::exp(-model.drag_per_s * h);
  const Eigen::Index count = s.x.cols();
  for (int sub = 0; sub < n; ++sub) {
    update_contractions(model, s, s.time_s);
    internal_and_scripted_forces(model, s.x, s.v, s.time_s, s, s.force);
    for (Eigen::Index i = 0; i < count; ++i) {
      const double w = model.inverse_mass[i];
      if (w == 0) continue;
      s.v.col(i) = drag * (s.v.col(i) + h * (model.gravity + w * s.force.col(i)));
    }
    drift(model, s, h, s.time_s + h);
    settle_on_floor(model, s, h);
    s.time_s += h;
  }
}

}  // namespace systole::sim
