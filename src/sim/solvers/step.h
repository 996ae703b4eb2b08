#pragma once
// One entry point for every solver, and the health check that stops a run that blew up.

#include <optional>
#include <string>

#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// Advances the body by dt_s with the model's solver. `coupling`, when given, ties the
/// particles to moving targets (training; XPBD only: Error(kInternal) otherwise).
void step(const Model& model, State& state, double dt_s, const Attachments* coupling = nullptr);

/// Tells the model's solver that the state was changed from outside between steps (a
/// contact impulse): a solver with history (projective dynamics' BDF2) restarts from it.
void restart_history(const Model& model, State& state);

/// What is wrong with a state, if anything: non-finite values, an extent far beyond the
/// rest shape's, or a collapsed volume. The text names the cause and the particle.
std::optional<std::string> diagnose(const Model& model, const State& state);

/// The remedy to print with a diagnosis.
std::string divergence_remedy(const Model& model);

}  // namespace systole::sim
