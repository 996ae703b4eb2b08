#pragma once
// Extended Position Based Dynamics with substeps: Macklin, Müller, Chentanez, "XPBD:
// Position-Based Simulation of Compliant Constrained Dynamics" (MIG 2016), stepped as in
// Macklin et al., "Small Steps in Physics Simulation" (SCA 2019): many substeps, one
// constraint iteration each, multipliers reset every substep.

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances `state` by dt_s with model.substeps substeps.
void xpbd_step(const Model& model, State& state, double dt_s);

/// One distance constraint C = |xb - xa| - rest (XPBD eq. 18, with the damping of eq. 26,
/// gamma = compliance * c / h = damping_s / h for c = k * damping_s). Moves xa and xb and
/// returns the multiplier change. `da`, `db` are the particles' motion this substep.
/// Inputs: positions and inverse masses (unit: 1/kg), rest (m), compliance alpha / h^2
/// (unit: m/(N s^2)), gamma (unit: 1).
double solve_distance(double* xa, double* xb, const double* da, const double* db, double wa, double wb,
                      double rest, double alpha_tilde, double gamma);

}  // namespace systole::sim
