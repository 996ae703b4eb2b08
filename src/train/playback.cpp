#include "train/playback.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "common/error.h"
#include "scene/tree.h"
#include "sim/from_scene.h"
#include "sim/motion_error.h"
#include "sim/solvers/step.h"
#include "world/frame_source.h"

namespace systole::train {
namespace {

/// `error_m` as a % of `motion_m`; a target that does not move is matched only exactly.
double share_of(double error_m, double motion_m) {
  if (motion_m > 0) return 100.0 * error_m / motion_m;
  return error_m > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

Problem make_problem(const scene::Scene& scene, std::size_t organ_index) {
  scene::Scene alone = scene;
  alone.organs = {scene.organs[organ_index]};
  alone.interactions.clear();
  world::FrameSource source(alone);
  world::OrganBody& body = source.world().organs.front();
  const scene::Organ& organ = alone.organs.front();
  Problem p{organ.name, std::move(body.model), source.world().dt_s, organ.target.rate_hz, 0, 0,
            load_target(organ, body.geometry), {}, {}, {}, 0, {}};
  // The target moves the organ's surface vertices, and training ties particle i to target
  // vertex i: a reduced body (a lattice) has other particles, so it is refused, not misread.
  if (p.target.particle_count() != p.model.particle_count()) {
    throw Error(ExitCode::kDataError,
                scene::where(organ.origin) + "organ '" + organ.name + "': its target moves the " +
                    std::to_string(p.target.particle_count()) + " vertices of its surface, and its body has " +
                    std::to_string(p.model.particle_count()) +
                    " particles (a reduced model, body.lattice); training ties each particle to its own target "
                    "vertex, so give this organ body.lattice: 0 to tune it");
  }
  const double steps_per_cycle = 1.0 / (p.rate_hz * p.dt_s);
  p.settle_steps = static_cast<int>(std::lround(organ.target.settle_cycles * steps_per_cycle));
  p.measure_steps = std::max(2, static_cast<int>(std::lround(organ.target.measure_cycles * steps_per_cycle)));
  p.target_size.assign(p.model.regions.size(), {});
  Eigen::Matrix3Xd x(3, p.model.particle_count());
  for (int k = 1; k <= p.measure_steps; ++k) {
    const double t = (p.settle_steps + k) * p.dt_s;
    p.target.positions(p.rate_hz * t, x);
    p.target_at_step.push_back(x);
    p.target_volume_m3.push_back(p.model.volume.enabled ? sim::enclosed_volume(x, p.model.volume.triangles) : 0.0);
    const std::vector<double> sizes = region_sizes(p.model, x);
    for (std::size_t r = 0; r < sizes.size(); ++r) p.target_size[r].push_back(sizes[r]);
  }
  p.target_motion_m = sim::rms_motion_m(p.target_at_step);
  p.target_region_motion_m.assign(p.model.regions.size(), 0.0);
  for (std::size_t r = 0; r < p.model.regions.size(); ++r) {
    std::vector<Eigen::Index> members;
    for (std::size_t i = 0; i < p.model.vertex_region.size(); ++i) {
      if (p.model.vertex_region[i] == static_cast<int>(r)) members.push_back(static_cast<Eigen::Index>(i));
    }
    if (members.empty()) continue;
    sim::Trajectory region(p.target_at_step.size(), Eigen::Matrix3Xd(3, members.size()));
    for (std::size_t k = 0; k < region.size(); ++k) {
      for (std::size_t m = 0; m < members.size(); ++m) region[k].col(m) = p.target_at_step[k].col(members[m]);
    }
    p.target_region_motion_m[r] = sim::rms_motion_m(region);
  }
  return p;
}

std::vector<double> region_sizes(const sim::Model& model, const Eigen::Matrix3Xd& x) {
  const std::size_t regions = model.regions.size();
  std::vector<Eigen::Vector3d> centroid(regions, Eigen::Vector3d::Zero()), rest_centroid = centroid;
  std::vector<int> count(regions, 0);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const int r = model.vertex_region.empty() ? -1 : model.vertex_region[i];
    if (r < 0) continue;
    centroid[r] += x.col(i);
    rest_centroid[r] += model.rest_positions.col(i);
    ++count[r];
  }
  std::vector<double> spread(regions, 0.0), rest_spread(regions, 0.0);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const int r = model.vertex_region.empty() ? -1 : model.vertex_region[i];
    if (r < 0) continue;
    spread[r] += (x.col(i) - centroid[r] / count[r]).squaredNorm();
    rest_spread[r] += (model.rest_positions.col(i) - rest_centroid[r] / count[r]).squaredNorm();
  }
  std::vector<double> size(regions, 1.0);
  for (std::size_t r = 0; r < regions; ++r) {
    if (rest_spread[r] > 0) size[r] = std::sqrt(spread[r] / rest_spread[r]);
  }
  return size;
}

double first_harmonic_phase(const std::vector<double>& samples, double t0_s, double dt_s, double rate_hz) {
  double c = 0, s = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double w = 2.0 * std::numbers::pi * rate_hz * (t0_s + double(k) * dt_s);
    c += samples[k] * std::cos(w);
    s += samples[k] * std::sin(w);
  }
  return std::atan2(s, c);
}

namespace {

/// The squared errors of a playback, summed over its measured steps.
struct ErrorSums {
  std::vector<double> region_sq;
  std::vector<int> region_count;
  double sq = 0, max_sq = 0, volume_sq = 0, mean_volume = 0;
};

/// Adds measured step k's errors of `state` against the target to `sums`, and each region's size to `e`.
void add_step_errors(const Problem& problem, const sim::Model& model, const sim::State& state, int k, ErrorSums& sums,
                     PlaybackError& e) {
  const Eigen::Matrix3Xd& target = problem.target_at_step[k];
  for (Eigen::Index i = 0; i < state.x.cols(); ++i) {
    const double d2 = (state.x.col(i) - target.col(i)).squaredNorm();
    sums.sq += d2;
    sums.max_sq = std::max(sums.max_sq, d2);
    const int r = model.vertex_region.empty() ? -1 : model.vertex_region[i];
    if (r >= 0) sums.region_sq[r] += d2, ++sums.region_count[r];
  }
  if (model.volume.enabled) {
    const double v = sim::enclosed_volume(state.x, model.volume.triangles);
    sums.volume_sq += (v - problem.target_volume_m3[k]) * (v - problem.target_volume_m3[k]);
    sums.mean_volume += problem.target_volume_m3[k];
  }
  const std::vector<double> sizes = region_sizes(model, state.x);
  for (std::size_t r = 0; r < sizes.size(); ++r) e.size[r].push_back(sizes[r]);
}

/// The playback's figures from its summed errors: as shares of the motion and the diagonal,
/// per region with the phase of its size.
void summarize(const Problem& problem, const sim::Model& model, Eigen::Index particles, const ErrorSums& sums,
               PlaybackError& e) {
  const double to_percent = 100.0 / model.rest_extent_m;
  const double samples = double(problem.measure_steps) * double(particles);
  const double rms_m = std::sqrt(sums.sq / samples);
  e.rms_pct_of_diagonal = rms_m * to_percent;
  e.rms_pct_of_motion = share_of(rms_m, problem.target_motion_m);
  e.max_pct_of_diagonal = std::sqrt(sums.max_sq) * to_percent;
  if (model.volume.enabled && sums.mean_volume > 0) {
    const double mean_volume = sums.mean_volume / problem.measure_steps;
    e.volume_percent = std::sqrt(sums.volume_sq / problem.measure_steps) / mean_volume * 100.0;
  }
  const double t0 = problem.measure_start_s() + problem.dt_s;
  for (std::size_t r = 0; r < model.regions.size(); ++r) {
    // A region the target hardly moves (a thousandth of the organ's motion) has no motion
    // to be a share of: NaN, which the report shows as "-".
    if (sums.region_count[r] > 0 && problem.target_region_motion_m[r] < 1e-3 * problem.target_motion_m) {
      e.regions[r].rms_pct_of_motion = std::numeric_limits<double>::quiet_NaN();
    } else if (sums.region_count[r] > 0) {
      e.regions[r].rms_pct_of_motion =
          share_of(std::sqrt(sums.region_sq[r] / sums.region_count[r]), problem.target_region_motion_m[r]);
    }
    const double played = first_harmonic_phase(e.size[r], t0, problem.dt_s, problem.rate_hz);
    const double wanted = first_harmonic_phase(problem.target_size[r], t0, problem.dt_s, problem.rate_hz);
    e.regions[r].phase_deg = std::remainder(played - wanted, 2.0 * std::numbers::pi) * 180.0 / std::numbers::pi;
  }
}

}  // namespace

PlaybackError play(const Problem& problem, const sim::Model& model) {
  PlaybackError e;
  const std::size_t regions = model.regions.size();
  e.regions.assign(regions, {});
  e.size.assign(regions, {});
  auto blew_up = [&] {
    e.diverged = true;
    e.rms_pct_of_motion = e.rms_pct_of_diagonal = e.max_pct_of_diagonal = e.volume_percent =
        std::numeric_limits<double>::infinity();
    for (auto& r : e.regions) r.rms_pct_of_motion = std::numeric_limits<double>::infinity();
    return e;
  };
  world::BodyPlayback playback(model, problem.dt_s);
  playback.run(problem.settle_steps);
  if (sim::diagnose(model, playback.state())) return blew_up();
  ErrorSums sums{std::vector<double>(regions, 0.0), std::vector<int>(regions, 0)};
  playback.run(problem.measure_steps, [&](int k) { add_step_errors(problem, model, playback.state(), k, sums, e); });
  if (sim::diagnose(model, playback.state()) || !std::isfinite(sums.sq)) return blew_up();
  summarize(problem, model, playback.state().x.cols(), sums, e);
  return e;
}

sim::Model with_regions(const sim::Model& base, const std::vector<scene::Region>& regions) {
  return sim::with_regions(base, sim::region_params(regions));
}

}  // namespace systole::train
