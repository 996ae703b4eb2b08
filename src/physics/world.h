#pragma once
// Around the organs: what kind of scripted touch, and the plane they cannot pass. Declared
// once for the scene (scene/world.h) and the simulator (sim/params.h).

#include <Eigen/Core>

namespace systole::physics {

enum class InteractionKind {
  kPoke,  ///< A force on the vertices near a point, over an interval (or all clip long, driven).
  kGrab,  ///< The vertices near a point follow a handle along a path, then are let go.
};

/// A plane the organs cannot pass (a table, the diaphragm's floor).
struct Floor {
  bool enabled = false;
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  ///< A point on the plane. unit: m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< Points to the free side (normalised). unit: 1
};

}  // namespace systole::physics
