#pragma once
// The one place the simulator meets the scene: a validated scene (scene/) translated into
// the simulator's own parameters (sim/params.h). The value types both share (drives, path
// keys, the floor, an interaction's kind: physics/) pass through as they are; what differs
// (names, where an entry was written, the clip's length) is translated here. Nothing else
// under src/sim/ includes scene/ (cmake/Architecture.cmake checks it), so the solvers
// never recompile for a scene change that is not theirs.

#include <string>
#include <vector>

#include "scene/scene.h"
#include "sim/contact/contact.h"
#include "sim/params.h"

namespace systole::sim {

Method method_params(scene::SolverMethod method);
RegionParams region_params(const scene::Region& region);
std::vector<RegionParams> region_params(const std::vector<scene::Region>& regions);
OrganParams organ_params(const scene::Organ& organ);

/// What organ `organ_name` of `scene` is built with at the world's step dt_s: the solver
/// (auto substeps when solver.dt is auto), gravity, floor, seed, the interactions that touch
/// the organ, and the clip's length in organ time (settling frames included).
ModelOptions model_options(const scene::Scene& scene, const std::string& organ_name, double dt_s);

/// The scene's contact pairs by organ index (every two organs but two colliders when it
/// lists none), each with its thickness and friction or the defaults; detection threads are
/// the solver's.
contact::Params contact_params(const scene::Scene& scene);

}  // namespace systole::sim
