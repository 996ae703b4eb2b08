#pragma once
// The distance constraint C = |xb - xa| - rest of every spring, in XPBD form: Macklin,
// Müller, Chentanez, "XPBD: Position-Based Simulation of Compliant Constrained Dynamics"
// (MIG 2016), eq. 18, with the damping of eq. 26.

namespace systole::sim {

/// One projection of C = |xb - xa| - rest: moves xa and xb and returns the multiplier change
///   dlambda = (-C - gamma grad C . (x - x_prev)) / ((1 + gamma) (wa + wb) + alpha_tilde)
/// (the multiplier's accumulated value is not used: one iteration per substep, lambda reset).
/// Inputs: positions xa, xb (m); da, db the particles' motion this substep (m); inverse
/// masses wa, wb (1/kg); rest (m); alpha_tilde = compliance / h^2 (m/(N s^2)); gamma =
/// compliance * c / h = damping_s / h for c = k damping_s (1). Returns 0 and moves nothing
/// when both ends are pinned or coincide (the direction is undefined).
double solve_distance(double* xa, double* xb, const double* da, const double* db, double wa, double wb,
                      double rest, double alpha_tilde, double gamma);

}  // namespace systole::sim
