#pragma once
// The paper's own integrator: a mass-spring-damper body stepped with symplectic
// (semi-implicit) Euler, v += h M^-1 f(x, v); x += h v (Kenwright & Sinmai §3; Hairer,
// Lubich & Wanner, "Geometric Numerical Integration", §I.1). Cheap per step, but stable
// only for h below about 2 / omega_max of the stiffest spring-mass pair, and tighter with
// stiff damping: the baseline the other solvers are measured against.

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances `state` by dt_s in model.substeps substeps.
void explicit_step(const Model& model, State& state, double dt_s);

}  // namespace systole::sim
