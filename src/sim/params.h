#pragma once
// What the simulator is built from: plain parameter structs in SI units, with no YAML and
// no scene in sight. sim/from_scene.h translates a validated scene into them; it is the one
// place the simulator meets the scene, so a change to captions or cameras never recompiles
// the solvers (docs/architecture.md).

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "electro/conduction.h"
#include "physics/drive.h"
#include "physics/world.h"

namespace systole::sim {

enum class Method { kXpbd, kExplicit, kImplicit, kProjective };

/// The method's name as scenes write it (solver.method).
inline const char* method_name(Method m) {
  switch (m) {
    case Method::kXpbd: return "xpbd";
    case Method::kExplicit: return "explicit";
    case Method::kImplicit: return "implicit";
    case Method::kProjective: return "projective";
  }
  return "unknown";
}

/// The drive (its waveform, its harmonics) and path keys are declared once, for the scene
/// and the simulator alike (physics/drive.h), so the bridge has nothing to copy field by field.
using physics::Drive;
using physics::Harmonic;
using physics::PathKey;
using physics::Waveform;

/// A region's own rhythm and material.
struct RegionParams {
  std::string name;
  Drive drive;
  double stiffness_scale = 1;  ///< Multiplies the body's stiffness. unit: 1
  double damping_scale = 1;    ///< Multiplies the body's damping. unit: 1
  bool pinned = false;         ///< Fixed in place (inverse mass 0).
  int detail = 1;              ///< Reduced model only: the region's voxels split into detail^3.
  std::vector<PathKey> motion;  ///< Pinned regions: offsets from rest over time; empty: at rest.
  /// > 0: the region's particles are held by zero-length springs (sharing this stiffness)
  /// to their rest places + tether_offset_m: a compliant hold beside `pinned`. unit: N/m
  double tether_stiffness_N_per_m = 0;
  Eigen::Vector3d tether_offset_m = Eigen::Vector3d::Zero();  ///< unit: m
};

/// The material of the whole body.
struct BodyParams {
  double mass_kg = 0.3;              ///< Total mass, spread over the particles. unit: kg
  double stiffness_N_per_m = 400;    ///< Stiffness of each surface-edge spring. unit: N/m
  double damping_s = 0.01;           ///< Stiffness-proportional damping time (c = k * damping_s). unit: s
  double volume_stiffness_Pa = 20000;  ///< Bulk modulus of the enclosed volume; 0 = none. unit: Pa
  double drag_per_s = 1.0;           ///< Velocity damping towards rest. unit: 1/s
  double bending_N_per_m = 0;        ///< Stiffness of the springs across each edge (0: none). unit: N/m
  int lattice = 0;                   ///< Reduced model: voxels along the longest side (0: full model).
  Drive volume_drive;                ///< Drives the rest volume V0(t) = V0 (1 + a phi(t - delay)).
  double fibre_tension = 0;          ///< Muscle with fibres: the fibres' tension beside the active strain. unit: 1
};

/// The blood of an anatomical heart's ventricles (sim/circulation.h).
struct BloodParams {
  bool enabled = false;
  double aortic_Pa = 0;     ///< unit: Pa
  double pulmonary_Pa = 0;  ///< unit: Pa
  double aortic_elastance_Pa_per_m3 = 0;     ///< unit: Pa/m^3
  double pulmonary_elastance_Pa_per_m3 = 0;  ///< unit: Pa/m^3
  double chordae = 0;                        ///< unit: 1
  double filling_Pa = 0;    ///< unit: Pa
};

/// One organ as the simulator sees it.
struct OrganParams {
  std::string name;
  std::string where;  ///< "file:line:column: " of the organ in its scene, for messages; may be empty.
  BodyParams body;
  BloodParams blood;
  /// The heart's own conduction system times each particle's beat (electro/conduction.h).
  bool electrophysiology = false;
  electro::ConductionParams conduction;
  std::vector<RegionParams> regions;
};

using physics::InteractionKind;  ///< Poke or grab (physics/world.h).

/// A scripted push or grab of the particles near a point.
struct InteractionParams {
  InteractionKind kind = InteractionKind::kPoke;
  std::string where;                                  ///< "file:line:column" of the entry, for messages.
  std::string key;                                    ///< "interactions[2].poke", for messages.
  Eigen::Vector3d at_m = Eigen::Vector3d::Zero();     ///< Centre of the touched patch at rest. unit: m
  double radius_m = 0.01;                             ///< Particles within it are touched. unit: m
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();  ///< kPoke: total force on the patch. unit: N
  double start_s = 0;                                 ///< kPoke. unit: s
  double duration_s = 0.1;                            ///< kPoke. unit: s
  Drive drive;                                        ///< kPoke: periodic when set.
  std::vector<PathKey> path;                          ///< kGrab: the handle's path.
  double stiffness_N_per_m = 2000;                    ///< kGrab: per particle. unit: N/m
};

using physics::Floor;  ///< A plane the body cannot pass (physics/world.h).

/// The solver settings.
struct SolverParams {
  Method method = Method::kXpbd;
  int substeps = 4;  ///< Substeps per step (ignored when auto_substeps).
  int iterations = 2;  ///< Projective: local/global iterations per substep.
  int threads = 1;   ///< Threads for the spring loops; the result is the same at any count.
  /// Choose the substeps from the body's stiffness and the step (solver.dt: auto).
  bool auto_substeps = false;
};

/// What a model is built with besides the organ: the solver, the world and the timeline.
struct ModelOptions {
  SolverParams solver;
  double dt_s = 1.0 / 240.0;  ///< The step the solver will be called with. unit: s
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< unit: m/s^2
  double clip_s = 0;          ///< The clip's length: rate ramps span it. unit: s
  std::uint64_t seed = 1;     ///< Irregular rhythms are seeded.
  std::vector<InteractionParams> interactions;  ///< Those touching this organ.
  Floor floor;
};

}  // namespace systole::sim
