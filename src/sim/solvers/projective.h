#pragma once
// Projective Dynamics: Bouaziz, Martin, Liu, Kavan, Pauly, "Projective Dynamics: Fusing
// Constraint Projections for Fast Simulation" (SIGGRAPH 2014), integrated with the
// second-order backward differentiation formula (BDF2; Hairer & Wanner, "Solving ODEs II",
// §III.1) instead of the paper's backward Euler.
//
// A step of size h minimizes, over the free particles' new positions x,
//
//   |x - x^|^2_M / (2 g^2) + sum_e k_e/2 |G_e x - p_e|^2 + sum_e c_e/(2g) |G_e (x - x~)|^2
//     + drag |x - x~|^2_M / (2g) + k_V/2 (V(x) - V0(t))^2 + grabs,
//
// where G_e x = x_b - x_a, p_e = L_e(t + h) (G_e x)/|G_e x| is the spring's projection onto
// its driven rest length, and BDF2 sets g = 2h/3, x~ = (4 x_n - x_(n-1))/3,
// x^ = x~ + g (4 v_n - v_(n-1))/3 + g^2 M^-1 f_ext (the first step, with no history, is
// backward Euler: g = h, x~ = x_n). Everything but the projections and the volume is
// quadratic in x with a matrix that never changes, because the dampers are isotropic
// (sim/forces.h):
//
//   A = M (1/g^2 + drag/g) + sum_e (k_e + c_e/g) G_e^T G_e   (+ k on grabbed particles),
//
// the same scalar matrix for x, y and z, factorized once (sparse LDL^T) and reused every
// step. Each local/global iteration projects every spring (local, parallel in principle)
// and solves with A (global); the volume term is linearized at the iterate (Gauss-Newton)
// and added as the rank-one k_V g g^T through the Sherman-Morrison formula, one
// back-substitution of six columns in all. The damping and the springs' linear part are
// exact in the matrix, so few iterations suffice: what is iterated is only the springs'
// rotation and the volume (docs/accuracy.md measures how many).
//
// A heart with blood (sim/circulation.h) adds, per ventricle whose valves are both shut, a
// hard constraint V_i(x) = V_shut,i: each iteration moves the global step's result along
// z_i = A^-1 f_i (f_i the blood's push at unit pressure at the step's start: the volume's
// gradient, but for the chordae's share) by the multipliers that bring the linearized
// volumes back, which are the ventricles' pressures; a filling or ejecting ventricle's
// pressure is a load on its faces in the right-hand side.

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances `state` by dt_s in model.substeps steps of Projective Dynamics with BDF2,
/// model.iterations local/global iterations each.
void projective_step(const Model& model, State& state, double dt_s);

/// Makes the next step start afresh with backward Euler: after an event that changed the
/// positions and velocities discontinuously (a contact impulse), BDF2's history is no longer
/// the state's past, and extrapolating from it would amplify the impulse (a multistep method
/// restarts after every event; Hairer & Wanner, "Solving ODEs II", §III.1).
void projective_restart(State& state);

}  // namespace systole::sim
