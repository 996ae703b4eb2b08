#pragma once
// The timeline of scripted interactions, evaluated the same way by every solver.

#include <Eigen/Core>

#include "sim/model.h"

namespace systole::sim {

/// The grab's handle at time t: a Catmull-Rom curve through the path keys (smooth, passing
/// through every key), clamped to the first and last key outside them. unit: m
Eigen::Vector3d handle_position(const Grab& grab, double t_s);

/// Whether the grab holds its patch at time t: from the first key to the last.
bool grab_active(const Grab& grab, double t_s);

/// How much of the poke's force acts at time t: 1 within [start, end) for a one-off push,
/// phi(t) for a periodic one, else 0. unit: 1
double poke_factor(const Poke& poke, double t_s, double ramp_s);

/// Keeps every particle on the free side of the model's floor, if it has one: a particle
/// found below the plane is moved onto it (frictionless, inelastic).
void resolve_floor_contact(const Model& model, Eigen::Matrix3Xd& x);

}  // namespace systole::sim
