#include "world/coupled_step.h"

#include <chrono>

#include "sim/solvers/step.h"
#include "world/world.h"

namespace systole::world {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<sim::contact::Body> contact_bodies(std::vector<OrganBody>& organs) {
  std::vector<sim::contact::Body> bodies;
  bodies.reserve(organs.size());
  for (OrganBody& o : organs) {
    sim::contact::Body b;
    b.name = o.model.name;
    b.triangles = &o.geometry.mesh.surface.triangles;
    b.embedding = &o.embedding;
    b.inverse_mass = &o.model.inverse_mass;
    b.movable = !o.collider;
    b.x = &o.state.x;
    b.v = &o.state.v;
    bodies.push_back(std::move(b));
  }
  return bodies;
}

void coupled_step(Coupling& coupling, std::vector<OrganBody>& organs, double dt_s) {
  std::vector<sim::contact::Body> bodies = contact_bodies(organs);
  const double h = dt_s / coupling.substeps;
  for (int sub = 0; sub < coupling.substeps; ++sub) {
    auto start = std::chrono::steady_clock::now();
    sim::contact::begin_step(bodies, coupling.work);
    coupling.contact_s += seconds_since(start);
    start = std::chrono::steady_clock::now();
    for (OrganBody& o : organs) {
      if (o.collider) {
        o.state.time_s += h;  // Still: only its clock moves.
        continue;
      }
      sim::step(o.model, o.state, h);
    }
    coupling.bodies_s += seconds_since(start);
    start = std::chrono::steady_clock::now();
    sim::contact::resolve(coupling.params, bodies, h, coupling.work);
    for (std::size_t b = 0; b < organs.size(); ++b)
      if (coupling.work.pushed[b]) sim::restart_history(organs[b].model, organs[b].state);
    coupling.contact_s += seconds_since(start);
  }
}

}  // namespace systole::world
