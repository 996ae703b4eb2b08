#pragma once
// Choosing the step for `solver.dt: auto`: from the highest drive frequency (accuracy of
// the rhythm) and the stiffest spring-mass pair (stability), so a scene pays only for the
// rhythm and stiffness it actually has.

#include <string>

#include "sim/model.h"

namespace systole::sim {

struct StepLimits {
  double max_step_s = 0;     ///< Longest step that samples the fastest drive component finely enough. unit: s
  double max_substep_s = 0;  ///< Longest substep the solver needs for this body. unit: s
  std::string reason;        ///< One line: which property set which limit.
};

/// The limits for `model` with its own solver method.
///  - every solver: at least 20 steps per period of the highest drive frequency;
///  - explicit: symplectic Euler is stable for h^2 w^2 + 2 h tau w^2 <= 4 on the stiffest
///    mode (w from a Gershgorin bound on M^-1 K, tau the damping time), with a 0.8 margin;
///  - xpbd: stable at any substep, with an error that grows with how far the constraints'
///    targets move per substep (rest lengths may change by at most 0.5% per substep) and
///    with the substep against the particles' damping time m / c (at most that);
///  - implicit: unconditionally stable; one substep per step.
StepLimits step_limits(const Model& model);

/// Largest Gershgorin bound on the squared angular frequency of the springs: max over
/// particles of w_i * sum over its springs of 2 k. unit: rad^2/s^2
double max_omega_squared(const Model& model);

/// Rough wall time one thread spends per simulated second stepping `model` at dt_s: its
/// springs (and volume triangles, each counted as a spring) times the solver's steps,
/// at the throughputs bench/sim_bench measured on the development machine (XPBD ~74 M,
/// explicit ~95 M spring updates per second; implicit ~0.2 M springs per second per step,
/// its conjugate-gradient solve; projective ~50 M per iteration, plus one for the step's
/// set-up, on the shipped heart). For `validate`; `systole bench` measures. unit: s/s
double estimated_cost_s_per_s(const Model& model, double dt_s);

/// Highest drive frequency of any region. unit: Hz
double highest_drive_frequency_hz(const std::vector<RegionParams>& regions);

/// Longest step that samples the regions' fastest drive component finely enough (20 steps
/// a period; 1 s when nothing is driven): step_limits' max_step_s, known before a body is
/// built, so a world can choose its step first. unit: s
double max_step_s(const std::vector<RegionParams>& regions);

}  // namespace systole::sim
