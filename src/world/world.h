#pragma once
// The simulated scene: every organ's geometry, body model and state, advanced together
// on one clock.

#include <functional>
#include <string>
#include <vector>

#include "mesh/organ.h"
#include "world/coupled_step.h"
#include "world/fold_watch.h"
#include "world/valves.h"
#include "scene/scene.h"
#include "sim/model.h"
#include "sim/reduced.h"
#include "sim/state.h"

namespace systole::world {

struct OrganBody {
  mesh::OrganGeometry geometry;  ///< The render mesh.
  sim::Model model;
  sim::State state;
  sim::Embedding embedding;      ///< How the render mesh follows a reduced model; empty: full model.
  FoldWatch folds;               ///< Lasting crumpling of a driven region (checked every frame).
  ValveMotion valves;            ///< An anatomical heart's valves, opened by the flow every frame.
  int lattice = 0;               ///< The body's lattice as built (0: full model).
  std::string body_reason;       ///< Why this body (choose_body), for `validate`.
  bool collider = false;         ///< A static collider: never stepped, touched under contact.
};

/// The body an organ gets: the generator's myocardium when the mesh has one (the anatomical
/// heart) and `body.lattice` is auto or 0 (it is that organ's full body); else the scene's
/// `body.lattice` when it gives a number; for `auto`, a lattice of kAutoLattice voxels for a mesh file that is open, in several pieces or over
/// kAutoLatticeVertices vertices (an atlas organ of many overlapping open parts: one
/// volumetric body moves them together and costs what its voxels cost, not its triangles),
/// else the full model (every vertex a particle: accurate on a closed surface).
struct BodyChoice {
  int lattice = 0;
  bool myocardium = false;  ///< The generator's own volumetric myocardium (sim/myocardium.h).
  std::string reason;
};
inline constexpr int kAutoLattice = 12;
inline constexpr int kAutoLatticeVertices = 50000;
BodyChoice choose_body(const scene::Organ& organ, const mesh::OrganGeometry& geometry);

/// The body's render-mesh positions now: the particles of a full model, or the mesh
/// embedded in a reduced model's lattice or a myocardium, valves opened. unit: m
void render_positions(const OrganBody& body, Eigen::Matrix3Xd& out);

struct World {
  std::vector<OrganBody> organs;
  int steps_per_frame = 1;  ///< The solver step divides the frame period exactly.
  double dt_s = 0;          ///< unit: s
  double fps = 30;          ///< Video frames per second. unit: 1/s
  double frame_s = 1.0 / 30;  ///< Organ time between two frames (scene::Output::frame_period_s). unit: s
  int start_frame = 0;      ///< Frames simulated before the clip's frame 0 (a loop's settling). unit: frames
  int frames_done = 0;      ///< Frames the world has been advanced through, counting start_frame.
  std::string step_reason;  ///< Why dt and substeps are what they are (for `validate`).
  /// Called after every solver step of every stepped organ (with the organ's index; its
  /// state.time_s is the step's end). The frame source (world/frame_source.h) sets it to
  /// call its listeners; consumers add theirs there (FrameSource::on_step).
  std::function<void(int organ, const OrganBody& body)> after_step;
  Eigen::Matrix3Xd scratch_positions;  ///< The health check's copy of a body's render positions.
  Coupling coupling;        ///< Contact between the organs (enabled: one coupled step for all).
};

/// Loads or generates every organ and builds its body. Under src/ only the frame source
/// calls it (world/frame_source.h): every consumer shares that one run. The step is the scene's dt (or, for
/// `dt: auto`, the longest every body allows: sim/step_size.h) rounded down so a whole
/// number of steps makes one frame.
World build_world(const scene::Scene& scene);

/// Steps every organ to the time of clip frame `frame`, start_s + frame * frame_s
/// (frames only move forward), checking the
/// bodies' health at every frame. Throws Error(kDiverged) with the frame, the time, the
/// cause and a remedy when a body blew up or a driven region stayed crumpled for longer
/// than its cycle (world/fold_watch.h).
void advance_to_frame(World& world, int frame);

}  // namespace systole::world
