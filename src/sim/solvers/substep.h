#pragma once
// What every solver does the same way inside a substep: the regions' rest-length
// contraction at a time, the drift of positions by the velocities (with kinematic regions
// placed), and the scripted pokes' and grabs' forces. One place for each, so the three solvers
// cannot drift apart (Kenwright & Sinmai §3: one body, several integrators).

#include <Eigen/Core>

#include "sim/drive.h"
#include "sim/interactions.h"
#include "sim/model.h"
#include "sim/state.h"

namespace systole::sim {

/// The regions' contraction a * phi(t) at t_s into state.region_contraction, then the
/// excited drives' (electrophysiology): where the solver evaluates its springs' rest lengths.
inline void update_contractions(const Model& model, State& s, double t_s) {
  region_contractions(model.regions, model.beat_boundaries, t_s, model.ramp_s, s.region_contraction);
  const Eigen::Index first = static_cast<Eigen::Index>(model.regions.size());
  for (int k = 0; k < model.excited.size(); ++k) {
    const Drive& d = model.regions[static_cast<std::size_t>(model.excited.region[k])].drive;
    s.region_contraction[first + k] = d.amplitude * activation(d, t_s - model.excited.delay_s[k], model.ramp_s);
  }
}

/// x_prev = x; x += h v; then the kinematic regions' particles placed at t_end_s.
inline void drift(const Model& model, State& s, double h_s, double t_end_s) {
  s.x_prev = s.x;
  s.x += h_s * s.v;
  move_kinematic_regions(model, t_end_s, s.x);
}

/// Calls add(particle, factor, force_per_particle_N) for every particle of every poke
/// acting at t_s (factor = poke_factor, never 0): the solver applies factor * force its
/// own way (a velocity kick, a force, a right-hand side).
template <class Add>
void for_each_poke(const Model& model, double t_s, Add&& add) {
  for (const Poke& p : model.pokes) {
    const double factor = poke_factor(p, t_s, model.ramp_s);
    if (factor == 0) continue;
    for (int i : p.particles) add(i, factor, p.force_per_particle_N);
  }
}

/// Calls add(particle, target_m, compliance_m_per_N) for every particle of every grab
/// holding at t_s (grab_active), in the model's order of grabs and each grab's order of
/// particles: target_m = the handle's position at t_s + the particle's rest offset, where
/// the grab's zero-length spring pulls it. The solver applies the spring its own way (a
/// force, a right-hand side and matrix term, an XPBD attachment).
template <class Add>
void for_each_grab(const Model& model, double t_s, Add&& add) {
  for (const Grab& g : model.grabs) {
    if (!grab_active(g, t_s)) continue;
    const Eigen::Vector3d handle = handle_position(g, t_s);
    for (std::size_t m = 0; m < g.particles.size(); ++m) {
      const Eigen::Vector3d target = handle + g.offsets_m[m];
      add(g.particles[m], target, g.compliance_m_per_N);
    }
  }
}

/// Explicit and implicit Euler after the drift: particles below the floor are put on it,
/// and their velocity loses the motion into it.
inline void settle_on_floor(const Model& model, State& s, double h_s) {
  if (!model.floor.enabled) return;
  resolve_floor_contact(model, s.x);
  s.v = (s.x - s.x_prev) / h_s;
}

}  // namespace systole::sim
