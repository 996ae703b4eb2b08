#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "sim/step.h"
#include "sim/step_size.h"

namespace systole::world {

namespace {

/// The frame period split into whole steps no longer than `max_step_s`.
int steps_per_frame(double frame_s, double max_step_s, bool round_down) {
  const double n = frame_s / max_step_s;
  // A step of 1e-300 s is in range for the schema but no int counts it: refuse it here,
  // before the resource limits (app/limits.h) can say what it would cost.
  if (!(n < 1e9)) {
    std::ostringstream m;
    m << "a step of " << max_step_s << " s makes " << n << " steps per frame of " << frame_s
      << " s; raise solver.dt or output.fps";
    throw Error(ExitCode::kDataError, m.str());
  }
  return std::max(1, static_cast<int>(round_down ? std::ceil(n - 1e-9) : std::lround(n)));
}

/// For `dt: auto`: the step every body allows, then each body's substeps.
void choose_steps(World& w, double frame_s) {
  double max_step = frame_s;
  std::vector<sim::StepLimits> limits;
  for (const auto& body : w.organs) {
    limits.push_back(sim::step_limits(body.model));
    max_step = std::min(max_step, limits.back().max_step_s);
  }
  w.steps_per_frame = steps_per_frame(frame_s, max_step, true);
  w.dt_s = frame_s / w.steps_per_frame;
  w.step_reason = "auto:";
  for (std::size_t o = 0; o < w.organs.size(); ++o) {
    auto& model = w.organs[o].model;
    model.substeps = std::max(1, static_cast<int>(std::ceil(w.dt_s / limits[o].max_substep_s - 1e-9)));
    w.step_reason += " " + model.name + ": " + limits[o].reason + ".";
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
  w.steps_per_frame = steps_per_frame(frame_s, scene.solver.dt_s, false);
  w.dt_s = frame_s / w.steps_per_frame;
  w.step_reason = "as the scene sets (solver.dt, solver.substeps), rounded so whole steps make a frame";
  for (const auto& organ : scene.organs) {
    OrganBody body;
    body.geometry = mesh::build_organ_geometry(organ);
    sim::ModelOptions options;
    options.solver = scene.solver;
    options.dt_s = w.dt_s;
    options.gravity = scene.gravity;
    options.clip_s = scene.output.start_frame * frame_s + scene.output.duration_s;  // Organ time at the clip's end.
    options.seed = scene.seed;
    options.floor = scene.floor;
    for (const auto& in : scene.interactions) {
      if (in.organ == organ.name) options.interactions.push_back(in);
    }
    if (organ.body.lattice > 0) {
      sim::ReducedBody reduced = sim::build_reduced_model(organ, body.geometry, options);
      body.model = std::move(reduced.model);
      body.embedding = std::move(reduced.embedding);
    } else {
      body.model = sim::build_model(organ, body.geometry, options);
    }
    body.state = sim::initial_state(body.model);
    w.organs.push_back(std::move(body));
  }
  if (scene.solver.auto_dt) choose_steps(w, frame_s);
  return w;
}

void render_positions(const OrganBody& body, Eigen::Matrix3Xd& out) { sim::embed(body.embedding, body.state.x, out); }

void advance_to_frame(World& w, int frame) {
  for (const int target = w.start_frame + frame; w.frames_done < target; ++w.frames_done) {
    for (auto& body : w.organs) {
      for (int k = 0; k < w.steps_per_frame; ++k) sim::step(body.model, body.state, w.dt_s);
      if (auto problem = sim::diagnose(body.model, body.state)) {
        std::ostringstream m;
        m << "simulation diverged at frame " << w.frames_done + 1 << " (t = " << body.state.time_s << " s): "
          << *problem << ". Remedy: " << sim::divergence_remedy(body.model) << ".";
        throw Error(ExitCode::kDiverged, m.str());
      }
    }
    if (w.after_frame) w.after_frame(w.frames_done + 1);
  }
}

}  // namespace systole::world
