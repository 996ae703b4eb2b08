#pragma once
// The timeline of scripted interactions, evaluated the same way by every solver.

#include <Eigen/Core>

#include "sim/model.h"

namespace systole::sim {

/// A path at time t: a Catmull-Rom curve through the keys (smooth, passing through every
/// key), held at the first and last key outside them. unit: m
Eigen::Vector3d path_position(const std::vector<PathKey>& path, double t_s);

/// The grab's handle at time t. unit: m
inline Eigen::Vector3d handle_position(const Grab& grab, double t_s) { return path_position(grab.path, t_s); }

/// Puts the particles of kinematic regions where their prescribed motion has them at time t.
void move_kinematic_regions(const Model& model, double t_s, Eigen::Matrix3Xd& x);

/// Whether the grab holds its patch at time t: from the first key to the last.
bool grab_active(const Grab& grab, double t_s);

/// How much of the poke's force acts at time t: 1 within [start, end) for a one-off push,
/// phi(t) for a periodic one, else 0. unit: 1
double poke_factor(const Poke& poke, double t_s, double ramp_s);

/// Keeps every particle on the free side of the model's floor, if it has one: a particle
/// found below the plane is moved onto it (frictionless, inelastic).
void resolve_floor_contact(const Model& model, Eigen::Matrix3Xd& x);

}  // namespace systole::sim
