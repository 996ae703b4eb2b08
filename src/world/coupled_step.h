#pragma once
// Organs that touch, stepped as one system: every organ advances by the same step, then
// contact (sim/contact/contact.h) keeps their surfaces apart, once per contact substep.
// Without a scene `contact` map the world steps each organ alone, as before.

#include <vector>

#include "sim/contact/contact.h"

namespace systole::world {

struct OrganBody;

/// Contact between the world's organs and what it has cost.
struct Coupling {
  bool enabled = false;
  int substeps = 1;                  ///< Contact steps per solver step.
  sim::contact::Params params;
  sim::contact::Workspace work;
  double bodies_s = 0;               ///< Wall time spent stepping the organs while coupled. unit: s
  double contact_s = 0;              ///< Wall time spent in contact (detection and projection). unit: s

  /// Contact's share of the coupled step's time so far. unit: 1
  double contact_share() const { return bodies_s + contact_s > 0 ? contact_s / (bodies_s + contact_s) : 0; }
};

/// The contact view of every organ (its render surface over its particles or embedding).
std::vector<sim::contact::Body> contact_bodies(std::vector<OrganBody>& organs);

/// Advances every organ but the colliders by dt_s in coupling.substeps contact steps: each
/// organ steps dt_s / substeps with its own solver, then contact resolves between them.
void coupled_step(Coupling& coupling, std::vector<OrganBody>& organs, double dt_s);

}  // namespace systole::world
