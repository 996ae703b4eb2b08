#pragma once
// Two soft balls that touch, for the contact tests: each a sim body built from an icosphere,
// its state, and the contact view of both (sim/contact/contact.h), stepped as the world's
// coupled step does: begin_step, each body's own step, resolve, restart after a push.

#include <Eigen/Core>
#include <vector>

#include "mesh/geometry.h"
#include "sim/contact/contact.h"
#include "sim/model.h"
#include "sim/solvers/step.h"
#include "sim/state.h"
#include "support/shapes.h"

namespace systole::test {

struct TwoBodies {
  mesh::OrganGeometry geometry[2];
  sim::Model model[2];
  sim::State state[2];
  std::vector<sim::contact::Body> bodies;
  sim::contact::Params params;
  sim::contact::Workspace work;

  /// Ball i of radius_m centred at centre[i], stiffness k_N_per_m[i], mass mass_kg[i]; the
  /// pair touches with `thickness_m` and `friction`; `movable[i]` false: a static collider;
  /// ball b squashed to flatten_b of its height (a thin disc).
  TwoBodies(sim::Method method, const Eigen::Vector3d centre[2], const double radius_m[2], const double k_N_per_m[2],
            const double mass_kg[2], double thickness_m = 0.002, double friction = 0.0, int threads = 1,
            const bool movable[2] = nullptr, double flatten_b = 1.0) {
    bodies.resize(2);
    for (int i = 0; i < 2; ++i) {
      mesh::TriangleMesh m = icosphere(radius_m[i], 3);
      for (auto& p : m.positions) {
        if (i == 1) p.y() *= flatten_b;  // A disc from a ball: flatten_b of its height.
        p += centre[i];
      }
      geometry[i] = geometry_of(m, std::vector<int>(m.positions.size(), -1));
      sim::OrganParams organ;
      organ.name = i == 0 ? "a" : "b";
      organ.body.stiffness_N_per_m = k_N_per_m[i];
      organ.body.mass_kg = mass_kg[i];
      sim::ModelOptions options;
      options.solver.method = method;
      options.solver.substeps = method == sim::Method::kXpbd ? 8 : method == sim::Method::kExplicit ? 40 : 1;
      options.solver.iterations = 5;
      options.solver.threads = threads;
      options.dt_s = 1.0 / 60;
      options.clip_s = 10;
      model[i] = sim::build_model(organ, geometry[i], options);
      state[i] = sim::initial_state(model[i]);
    }
    for (int i = 0; i < 2; ++i) {
      bodies[i] = {model[i].name, &geometry[i].mesh.surface.triangles, nullptr, &model[i].inverse_mass,
                   movable == nullptr || movable[i], &state[i].x, &state[i].v};
    }
    params.pairs = {{0, 1, thickness_m, friction}};
    params.threads = threads;
  }

  /// One coupled step of dt_s (world/coupled_step.cpp does the same for the organs).
  void step(double dt_s) {
    sim::contact::begin_step(bodies, work);
    for (int i = 0; i < 2; ++i)
      if (bodies[i].movable) sim::step(model[i], state[i], dt_s);
    sim::contact::resolve(params, bodies, dt_s, work);
    for (int i = 0; i < 2; ++i)
      if (work.pushed[i]) sim::restart_history(model[i], state[i]);
  }

  /// Kinetic energy of both bodies. unit: J
  double kinetic_energy() const {
    double e = 0;
    for (int b = 0; b < 2; ++b)
      for (Eigen::Index i = 0; i < state[b].v.cols(); ++i)
        if (model[b].inverse_mass[i] > 0) e += 0.5 / model[b].inverse_mass[i] * state[b].v.col(i).squaredNorm();
    return e;
  }

  /// The gap along y between a's lowest and b's highest vertex (a above b). unit: m
  double gap_m() const { return state[0].x.row(1).minCoeff() - state[1].x.row(1).maxCoeff(); }
};

}  // namespace systole::test
