#pragma once
// Around the organs: the solver, the camera, lights, scripted interactions and the floor.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "physics/world.h"
#include "scene/drive.h"
#include "scene/origin.h"

namespace systole::scene {

// ---------------------------------------------------------------------------------------
// Solver, view and output.

enum class SolverMethod { kXpbd, kExplicit, kImplicit, kProjective };

/// The name the scene gives a solver ("xpbd", "explicit", "implicit").
inline const char* method_name(SolverMethod m) {
  switch (m) {
    case SolverMethod::kXpbd: return "xpbd";
    case SolverMethod::kExplicit: return "explicit";
    case SolverMethod::kImplicit: return "implicit";
    case SolverMethod::kProjective: return "projective";
  }
  return "?";
}

struct Solver {
  SolverMethod method = SolverMethod::kProjective;
  bool auto_dt = false;        ///< Choose dt from the drive and stiffness (sim core issue).
  double dt_s = 1.0 / 60.0;    ///< Step size. unit: s
  int substeps = 1;            ///< Substeps per step (XPBD, explicit, projective). unit: 1
  int iterations = 2;          ///< Projective: local/global iterations per substep. unit: 1
  int threads = 1;             ///< Threads for the simulation's spring loops; the result is the same at any count.
  Origin origin;
};

/// A key of a camera path: where the eye is and what it looks at, at a time.
struct CameraKey {
  double time_s = 0;                                     ///< unit: s
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< unit: m
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();    ///< unit: m
};

/// A turntable: the eye turns about the axis through the target at a constant speed.
struct Orbit {
  bool enabled = false;
  double speed_rad_per_s = 0.3490658503988659;  ///< 20 deg/s; negative turns the other way. unit: rad/s
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  ///< Normalised. unit: 1
};

/// The camera at time 0 (position, target) and how it moves: fixed, an orbit, or a path
/// (app/camera_motion.h gives the camera at any time).
struct Camera {
  /// No position or path given (or `camera: auto`): clip/camera_framing.h places the eye on
  /// +z of the organs' bounding sphere, looking at its centre, so that it fills `fill` of
  /// the frame's smaller side. position_m and target_m hold the result once placed.
  bool automatic = true;
  double fill = 0.8;  ///< unit: 1
  Eigen::Vector3d position_m = Eigen::Vector3d(0, 0, 0.4);  ///< unit: m
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();       ///< unit: m
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();            ///< unit: 1
  double fov_rad = 0.6981317007977318;                      ///< Vertical field of view (40 deg). unit: rad
  Orbit orbit;
  std::vector<CameraKey> path;  ///< When not empty: Catmull-Rom through the keys, held outside them.
};

struct Light {
  Eigen::Vector3d direction = Eigen::Vector3d(-0.4, -0.6, -1.0);  ///< Direction the light travels. unit: 1
  Color color = Color(1, 1, 1);
  double intensity = 1;  ///< unit: 1
};

// ---------------------------------------------------------------------------------------
// Scripted interactions and contact.

using physics::InteractionKind;  ///< Poke or grab (physics/world.h).

struct Interaction {
  InteractionKind kind = InteractionKind::kPoke;
  std::string organ;                                 ///< Name of the organ touched.
  Eigen::Vector3d at_m = Eigen::Vector3d::Zero();    ///< Centre of the touched patch, world space at rest. unit: m
  double radius_m = 0.01;                            ///< Vertices within this distance of at_m are touched. unit: m
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero(); ///< kPoke: total force, shared by the patch's vertices. unit: N
  double start_s = 0;                                ///< kPoke: when the push starts. unit: s
  double duration_s = 0.1;                           ///< kPoke: how long it lasts. unit: s
  Drive drive;                                       ///< kPoke: when set, the force follows phi(t) all clip long (a periodic push).
  std::vector<PathKey> path;                         ///< kGrab: the handle's path, smoothly interpolated; released after the last key.
  double stiffness_N_per_m = 2000;                   ///< kGrab: stiffness holding each vertex to the handle. unit: N/m
  Origin origin;
};

/// Two organs that touch, with their own thickness and friction (else contact's defaults).
struct ContactPair {
  std::vector<std::string> organs;  ///< The two organs' names.
  bool has_thickness = false;
  double thickness_m = 0;   ///< Used when has_thickness. unit: m
  bool has_friction = false;
  double friction = 0;      ///< Used when has_friction. unit: 1
  Origin origin;
};

/// Contact between organs (docs/contact.md): off unless the scene has a `contact` map; then
/// every organ steps in one coupled step and the pairs' surfaces are kept apart.
struct Contact {
  bool enabled = false;
  double thickness_m = 0.002;     ///< Default gap kept between two surfaces. unit: m
  double friction = 0.1;          ///< Default Coulomb coefficient. unit: 1
  int iterations = 4;             ///< Projection passes over the contacts per contact step. unit: 1
  int substeps = 1;               ///< Contact steps per solver step. unit: 1
  std::vector<ContactPair> pairs;  ///< Empty: every two organs (not two colliders).
  Origin origin;
};

using physics::Floor;  ///< A plane the organs cannot pass (physics/world.h).

}  // namespace systole::scene
