#include "sim/solvers/step.h"

#include <cmath>
#include <sstream>

#include "common/error.h"
#include "sim/solvers/explicit_euler.h"
#include "sim/solvers/implicit_euler.h"
#include "sim/solvers/projective.h"
#include "sim/solvers/xpbd.h"

namespace systole::sim {

void step(const Model& model, State& state, double dt_s, const Attachments* coupling) {
  if (coupling && coupling->enabled() && model.method != Method::kXpbd) {
    throw Error(ExitCode::kInternal, "attachments (training's coupling) are solved by XPBD only");
  }
  switch (model.method) {
    case Method::kXpbd:
      xpbd_step(model, state, dt_s, coupling);
      return;
    case Method::kExplicit:
      explicit_step(model, state, dt_s);
      return;
    case Method::kImplicit:
      implicit_step(model, state, dt_s);
      return;
    case Method::kProjective:
      projective_step(model, state, dt_s);
      return;
  }
  throw Error(ExitCode::kInternal, "sim::step: unknown solver method");
}

void restart_history(const Model& model, State& state) {
  if (model.method == Method::kProjective) projective_restart(state);
}

std::optional<std::string> diagnose(const Model& model, const State& s) {
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    if (!s.x.col(i).allFinite() || !s.v.col(i).allFinite()) {
      std::ostringstream m;
      m << "particle " << i << " of '" << model.name << "' has a non-finite position or velocity";
      return m.str();
    }
  }
  if (s.x.cols() == 0) return std::nullopt;
  // Fifty body lengths a second: faster than any poke or beat moves tissue; an unstable
  // step gets there long before positions overflow.
  const double speed_limit = 50.0 * model.rest_extent_m;
  for (Eigen::Index i = 0; i < s.v.cols(); ++i) {
    if (s.v.col(i).norm() > speed_limit) {
      std::ostringstream m;
      m << "particle " << i << " of '" << model.name << "' moves at " << s.v.col(i).norm()
        << " m/s, beyond the " << speed_limit << " m/s no tissue reaches (kinetic energy is exploding)";
      return m.str();
    }
  }
  const double extent = (s.x.rowwise().maxCoeff() - s.x.rowwise().minCoeff()).norm();
  // Ten times the rest size: no drive or poke of a soft organ does that; an unstable step does.
  if (model.rest_extent_m > 0 && extent > 10.0 * model.rest_extent_m) {
    std::ostringstream m;
    m << "'" << model.name << "' grew to " << extent / model.rest_extent_m << " times its rest size";
    return m.str();
  }
  if (model.volume.enabled) {
    const double v = enclosed_volume(s.x, model.volume.triangles);
    if (v < 0.1 * model.volume.rest_m3) {
      std::ostringstream m;
      m << "'" << model.name << "' collapsed to " << 100.0 * v / model.volume.rest_m3 << "% of its rest volume";
      return m.str();
    }
  }
  return std::nullopt;
}

std::string divergence_remedy(const Model& model) {
  switch (model.method) {
    case Method::kXpbd:
      return "raise solver.substeps or lower solver.dt, or lower body.stiffness / region stiffness ratios";
    case Method::kExplicit:
      return "lower solver.dt (explicit springs need dt < 2 / sqrt(k / m)), or use solver.method: xpbd";
    case Method::kImplicit:
      return "lower solver.dt, or lower the drive amplitude";
    case Method::kProjective:
      return "lower solver.dt or raise solver.iterations, or lower the drive amplitude";
  }
  return "lower solver.dt";
}

}  // namespace systole::sim
