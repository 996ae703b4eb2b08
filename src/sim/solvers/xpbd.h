#pragma once
// Extended Position Based Dynamics with substeps: Macklin, Müller, Chentanez, "XPBD:
// Position-Based Simulation of Compliant Constrained Dynamics" (MIG 2016), stepped as in
// Macklin et al., "Small Steps in Physics Simulation" (SCA 2019): many substeps, one
// constraint iteration each, multipliers reset every substep.

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances `state` by dt_s with model.substeps substeps; `coupling`, when given, ties the
/// particles to their training targets. The constraints are sim/constraints/.
void xpbd_step(const Model& model, State& state, double dt_s, const Attachments* coupling = nullptr);

}  // namespace systole::sim
