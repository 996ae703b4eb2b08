#include "app/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "sim/step.h"

namespace systole::app {

World build_world(const scene::Scene& scene) {
  World w;
  w.fps = scene.output.fps;
  const double frame_s = 1.0 / scene.output.fps;
  w.steps_per_frame = std::max(1, static_cast<int>(std::lround(frame_s / scene.solver.dt_s)));
  w.dt_s = frame_s / w.steps_per_frame;
  for (const auto& organ : scene.organs) {
    OrganBody body;
    body.geometry = mesh::build_organ_geometry(organ);
    sim::ModelOptions options;
    options.solver = scene.solver;
    options.dt_s = w.dt_s;
    options.gravity = scene.gravity;
    options.clip_s = scene.output.duration_s;
    options.floor = scene.floor;
    for (const auto& in : scene.interactions) {
      if (in.organ == organ.name) options.interactions.push_back(in);
    }
    body.model = sim::build_model(organ, body.geometry, options);
    body.state = sim::initial_state(body.model);
    w.organs.push_back(std::move(body));
  }
  return w;
}

void advance_to_frame(World& w, int frame) {
  for (; w.frames_done < frame; ++w.frames_done) {
    for (auto& body : w.organs) {
      for (int k = 0; k < w.steps_per_frame; ++k) sim::step(body.model, body.state, w.dt_s);
      if (auto problem = sim::diagnose(body.model, body.state)) {
        std::ostringstream m;
        m << "simulation diverged at frame " << w.frames_done + 1 << " (t = " << body.state.time_s << " s): "
          << *problem << ". Remedy: " << sim::divergence_remedy(body.model) << ".";
        throw Error(ExitCode::kDiverged, m.str());
      }
    }
  }
}

}  // namespace systole::app
