#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "scene/tree.h"
#include "sim/from_scene.h"
#include "sim/myocardium.h"
#include "sim/solvers/step.h"
#include "sim/solvers/step_size.h"

namespace systole::world {

namespace {

/// The frame period split into whole steps no longer than `max_step_s`.
int steps_per_frame(double frame_s, double max_step_s, bool round_down) {
  const double n = frame_s / max_step_s;
  // A step of 1e-300 s is in range for the schema but no int counts it: refuse it here,
  // before the resource limits (clip/limits.h) can say what it would cost.
  if (!(n < 1e9)) {
    std::ostringstream m;
    m << "a step of " << max_step_s << " s makes " << n << " steps per frame of " << frame_s
      << " s; raise solver.dt or output.fps";
    throw Error(ExitCode::kDataError, m.str());
  }
  return std::max(1, static_cast<int>(round_down ? std::ceil(n - 1e-9) : std::lround(n)));
}

/// For `dt: auto`: the longest step every organ's drives allow (each body then chooses its
/// own substeps for it when it is built).
double auto_max_step_s(const scene::Scene& scene, double frame_s) {
  double max_step = frame_s;
  for (const auto& organ : scene.organs) max_step = std::min(max_step, sim::max_step_s(sim::region_params(organ.regions)));
  return max_step;
}

/// Contact as the scene asks: every organ of a pair needs a closed surface (a vertex is
/// inside or outside it).
void set_up_contact(const scene::Scene& scene, World& w) {
  if (!scene.contact.enabled) return;
  w.coupling.enabled = true;
  w.coupling.substeps = scene.contact.substeps;
  w.coupling.params = sim::contact_params(scene);
  for (const sim::contact::PairParams& p : w.coupling.params.pairs) {
    for (const int b : {p.body_a, p.body_b}) {
      const OrganBody& body = w.organs[b];
      if (body.geometry.report.closed() && !body.geometry.mesh.surface.triangles.empty()) continue;
      std::ostringstream m;
      m << scene.path << ": contact: organ '" << scene.organs[b].name
        << "' has an open or non-manifold surface; contact keeps closed surfaces apart (a vertex is inside or "
           "outside one), so close the mesh or leave the organ out of contact.pairs";
      throw Error(ExitCode::kDataError, m.str());
    }
  }
}

}  // namespace

World build_world(const scene::Scene& scene) {
  if (scene.output.frame_count() < 1) {
    std::ostringstream m;
    m << scene.path << ": output.duration (" << scene.output.duration_s << " s) x output.fps (" << scene.output.fps
      << ") gives no frame; the clip needs at least one";
    throw Error(ExitCode::kDataError, m.str());
  }
  World w;
  w.fps = scene.output.fps;
  const double frame_s = scene.output.frame_period_s();
  w.frame_s = frame_s;
  w.start_frame = scene.output.start_frame;
  if (scene.solver.auto_dt) {
    w.steps_per_frame = steps_per_frame(frame_s, auto_max_step_s(scene, frame_s), true);
    w.step_reason = "auto:";
  } else {
    w.steps_per_frame = steps_per_frame(frame_s, scene.solver.dt_s, false);
    w.step_reason = "as the scene sets (solver.dt, solver.substeps), rounded so whole steps make a frame";
  }
  w.dt_s = frame_s / w.steps_per_frame;
  for (const auto& organ : scene.organs) {
    OrganBody body;
    body.geometry = mesh::build_organ_geometry(organ);
    const BodyChoice choice = choose_body(organ, body.geometry);
    body.lattice = choice.lattice;
    body.body_reason = choice.reason;
    sim::OrganParams params = sim::organ_params(organ);
    params.body.lattice = choice.lattice;
    const sim::ModelOptions options = sim::model_options(scene, organ.name, w.dt_s);
    if (organ.blood.enabled && (!choice.myocardium || scene.solver.method != scene::SolverMethod::kProjective)) {
      std::ostringstream m;
      m << where(organ.origin) << "organs[" << w.organs.size() << "].blood: "
        << (choice.myocardium ? "the blood is held by the projective solver; set solver.method: projective"
                              : "blood fills the generated anatomical heart's ventricles (mesh: {procedural: "
                                "anatomical_heart} with body.lattice auto or 0); this organ has none");
      throw Error(ExitCode::kDataError, m.str());
    }
    if (choice.myocardium) {
      sim::ReducedBody myocardium = sim::build_myocardium_model(params, body.geometry, options);
      body.model = std::move(myocardium.model);
      body.embedding = std::move(myocardium.embedding);
      body.valves = valve_motion(body.geometry.mesh.anatomy, body.geometry.mesh.surface.positions, body.model.circulation);
    } else if (choice.lattice > 0) {
      sim::ReducedBody reduced = sim::build_reduced_model(params, body.geometry, options);
      body.model = std::move(reduced.model);
      body.embedding = std::move(reduced.embedding);
    } else {
      body.model = sim::build_model(params, body.geometry, options);
    }
    body.state = sim::initial_state(body.model);
    body.folds = FoldWatch(organ, body.geometry);
    body.collider = organ.collider;
    if (scene.solver.auto_dt) w.step_reason += " " + body.model.name + ": " + sim::step_limits(body.model).reason + ".";
    w.organs.push_back(std::move(body));
  }
  set_up_contact(scene, w);
  return w;
}

BodyChoice choose_body(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  // A generator's myocardium is the organ's full body: `body.lattice: 0` (and auto) take it.
  if (!geometry.mesh.anatomy.empty() && (organ.body.lattice == scene::Body::kLatticeAuto || organ.body.lattice == 0)) {
    const mesh::Myocardium& m = geometry.mesh.anatomy.myocardium;
    return {0, true, std::string(organ.body.lattice == 0 ? "as the scene sets (body.lattice: 0)" : "auto") +
                         ": the generated myocardium, " + std::to_string(m.nodes.size()) +
                         " particles through the walls and " + std::to_string(m.springs.size()) +
                         " springs along and across the muscle fibres"};
  }
  if (organ.body.lattice != scene::Body::kLatticeAuto) {
    return {organ.body.lattice, false, "as the scene sets (body.lattice: " + std::to_string(organ.body.lattice) + ")"};
  }
  const mesh::MeshReport& r = geometry.report;
  std::vector<std::string> why;
  if (!organ.mesh.file.empty()) {
    if (!r.closed()) why.push_back("the surface is open");
    if (r.components > 1) why.push_back("it is in " + std::to_string(r.components) + " pieces");
    if (r.vertices > kAutoLatticeVertices) why.push_back("it has " + std::to_string(r.vertices) + " vertices");
  }
  if (why.empty()) {
    return {0, false, "auto: full model, every vertex a particle (" +
                   std::string(organ.mesh.file.empty() ? "a generated organ" : "a closed surface in one piece") + ")"};
  }
  std::string text = "auto: lattice " + std::to_string(kAutoLattice) + ", since ";
  for (std::size_t i = 0; i < why.size(); ++i) text += (i == 0 ? "" : i + 1 == why.size() ? " and " : ", ") + why[i];
  return {kAutoLattice, false, text + ": one volumetric body moves the parts together; body.lattice: 0 simulates every vertex"};
}

void render_positions(const OrganBody& body, Eigen::Matrix3Xd& out) {
  sim::embed(body.embedding, body.state.x, out);
  open_valves(body.valves, out);
}

void advance_to_frame(World& w, int frame) {
  for (const int target = w.start_frame + frame; w.frames_done < target; ++w.frames_done) {
    if (w.coupling.enabled) {
      for (int k = 0; k < w.steps_per_frame; ++k) {
        coupled_step(w.coupling, w.organs, w.dt_s);
        for (std::size_t o = 0; w.after_step && o < w.organs.size(); ++o) {
          if (!w.organs[o].collider) w.after_step(static_cast<int>(o), w.organs[o]);
        }
      }
    }
    for (std::size_t o = 0; o < w.organs.size(); ++o) {
      OrganBody& body = w.organs[o];
      if (body.collider && !w.coupling.enabled) body.state.time_s += w.frame_s;  // Drawn, never simulated.
      if (!w.coupling.enabled && !body.collider) {
        for (int k = 0; k < w.steps_per_frame; ++k) {
          sim::step(body.model, body.state, w.dt_s);
          if (w.after_step) w.after_step(static_cast<int>(o), body);
        }
      }
      if (auto problem = sim::diagnose(body.model, body.state)) {
        std::ostringstream m;
        m << "simulation diverged at frame " << w.frames_done + 1 << " (t = " << body.state.time_s << " s): "
          << *problem << ". Remedy: " << sim::divergence_remedy(body.model) << ".";
        throw Error(ExitCode::kDiverged, m.str());
      }
      const bool folds_due = body.folds.due(body.state.time_s);
      // A full model's particles are its render vertices; a lattice's are embedded first,
      // once for the valves (which measure it with the leaflets closed) and the watch.
      if (!body.embedding.empty() && (folds_due || !body.valves.empty())) {
        sim::embed(body.embedding, body.state.x, w.scratch_positions);
        if (!body.valves.empty()) update_valves(body.valves, w.scratch_positions, w.frame_s, body.state.chambers);
        open_valves(body.valves, w.scratch_positions);
      }
      if (!folds_due) continue;
      const Eigen::Matrix3Xd& surface = body.embedding.empty() ? body.state.x : w.scratch_positions;
      if (auto crumpled = body.folds.update(surface, body.state.time_s)) {
        std::ostringstream m;
        m << "simulation stopped at frame " << w.frames_done + 1 << " (t = " << body.state.time_s << " s): " << *crumpled
          << ". Remedy: give the organ a volumetric body (body.lattice: 12) so its parts move as one, raise "
             "body.bending, or lower the drive's amplitude.";
        throw Error(ExitCode::kDiverged, m.str());
      }
    }
  }
}

}  // namespace systole::world
