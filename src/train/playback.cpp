#include "train/playback.h"

#include <algorithm>
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
  const auto& surface = body.geometry.mesh.surface.positions;
  Eigen::Matrix3Xd rest(3, static_cast<Eigen::Index>(surface.size()));
  for (std::size_t v = 0; v < surface.size(); ++v) rest.col(static_cast<Eigen::Index>(v)) = surface[v];
  // The target moves the render surface; the body, whatever it is (every vertex a particle,
  // a lattice, a myocardium), is tied to it and measured through the surface's embedding.
  Problem p{organ.name,   std::move(body.model), std::move(body.embedding), std::move(rest), body.geometry.vertex_region,
            source.world().dt_s, organ.target.rate_hz, 0, 0, load_target(organ, body.geometry), {}, {}, {}, 0, {}, {}};
  p.valves = std::move(body.valves);
  const double steps_per_cycle = 1.0 / (p.rate_hz * p.dt_s);
  p.settle_steps = static_cast<int>(std::lround(organ.target.settle_cycles * steps_per_cycle));
  p.measure_steps = std::max(2, static_cast<int>(std::lround(organ.target.measure_cycles * steps_per_cycle)));
  p.target_size.assign(p.model.regions.size(), {});
  Eigen::Matrix3Xd x;
  for (int k = 1; k <= p.measure_steps; ++k) {
    const double t = (p.settle_steps + k) * p.dt_s;
    p.target.positions(p.rate_hz * t, x);
    p.target_at_step.push_back(x);
    p.target_volume_m3.push_back(p.model.volume.enabled && p.embedding.empty()
                                     ? sim::enclosed_volume(x, p.model.volume.triangles)
                                     : 0.0);
    const std::vector<double> sizes = region_sizes(p, x);
    for (std::size_t r = 0; r < sizes.size(); ++r) p.target_size[r].push_back(sizes[r]);
  }
  p.target_motion_m = sim::rms_motion_m(p.target_at_step);
  p.target_region_motion_m.assign(p.model.regions.size(), 0.0);
  for (std::size_t r = 0; r < p.model.regions.size(); ++r) {
    std::vector<Eigen::Index> members;
    for (std::size_t i = 0; i < p.surface_region.size(); ++i) {
      if (p.surface_region[i] == static_cast<int>(r)) members.push_back(static_cast<Eigen::Index>(i));
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

void surface_of(const Problem& problem, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& surface) {
  sim::embed(problem.embedding, x, surface);
}

std::vector<double> region_sizes(const Problem& problem, const Eigen::Matrix3Xd& x) {
  const std::size_t regions = problem.model.regions.size();
  const Eigen::Matrix3Xd& rest = problem.surface_rest;
  auto region_of = [&](Eigen::Index i) {
    return problem.surface_region.empty() ? -1 : problem.surface_region[static_cast<std::size_t>(i)];
  };
  std::vector<Eigen::Vector3d> centroid(regions, Eigen::Vector3d::Zero()), rest_centroid = centroid;
  std::vector<int> count(regions, 0);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const int r = region_of(i);
    if (r < 0) continue;
    centroid[r] += x.col(i);
    rest_centroid[r] += rest.col(i);
    ++count[r];
  }
  std::vector<double> spread(regions, 0.0), rest_spread(regions, 0.0);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const int r = region_of(i);
    if (r < 0) continue;
    spread[r] += (x.col(i) - centroid[r] / count[r]).squaredNorm();
    rest_spread[r] += (rest.col(i) - rest_centroid[r] / count[r]).squaredNorm();
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

ErrorMeter::ErrorMeter(const Problem& problem, Valves valves)
    : problem_(problem), valves_(problem.valves), valves_cue_(valves) {
  const std::size_t regions = problem.model.regions.size();
  region_sq_.assign(regions, 0.0);
  region_count_.assign(regions, 0);
  error_.regions.assign(regions, {});
  error_.size.assign(regions, {});
}

namespace {

/// Each valve opened as far as the target's leaflets are from the closed ones along their
/// opening (mean over the leaflets' vertices, 0 .. 1): tied to the target, as the body is.
void open_as_the_target(world::ValveMotion& valves, const Eigen::Matrix3Xd& target, Eigen::Matrix3Xd& surface) {
  for (world::ValveMotion::Leaflets& valve : valves.valves) {
    double sum = 0;
    for (std::size_t i = 0; i < valve.vertices.size(); ++i) {
      const Eigen::Vector3d delta = valve.open_delta.col(static_cast<Eigen::Index>(i));
      const int v = valve.vertices[i];
      const double length_sq = delta.squaredNorm();
      if (length_sq > 0) sum += std::clamp((target.col(v) - surface.col(v)).dot(delta) / length_sq, 0.0, 1.0);
    }
    valve.opening = valve.vertices.empty() ? 0.0 : sum / static_cast<double>(valve.vertices.size());
  }
  world::open_valves(valves, surface);
}

}  // namespace

void ErrorMeter::take_surface(const sim::State& state, const Eigen::Matrix3Xd* target) {
  surface_of(problem_, state.x, surface_);
  if (valves_.empty()) return;
  if (valves_cue_ == Valves::kAsTheTarget) {
    if (target != nullptr) open_as_the_target(valves_, *target, surface_);
    return;
  }
  world::update_valves(valves_, surface_, problem_.dt_s, state.chambers);
  world::open_valves(valves_, surface_);
}

void ErrorMeter::watch(const sim::State& state) { take_surface(state, nullptr); }

void ErrorMeter::add(int k, const sim::State& state) {
  const Eigen::Matrix3Xd& x = state.x;
  const Eigen::Matrix3Xd& target = problem_.target_at_step[static_cast<std::size_t>(k)];
  take_surface(state, &target);
  if (error_sum_.cols() != surface_.cols()) error_sum_ = Eigen::Matrix3Xd::Zero(3, surface_.cols());
  error_sum_ += surface_ - target;
  for (Eigen::Index i = 0; i < surface_.cols(); ++i) {
    const double d2 = (surface_.col(i) - target.col(i)).squaredNorm();
    sq_ += d2;
    max_sq_ = std::max(max_sq_, d2);
    const int r = problem_.surface_region.empty() ? -1 : problem_.surface_region[static_cast<std::size_t>(i)];
    if (r >= 0) region_sq_[r] += d2, ++region_count_[r];
  }
  // The enclosed volume where the particles are the surface (a lattice's hull is not it).
  if (problem_.model.volume.enabled && problem_.embedding.empty()) {
    const double v = sim::enclosed_volume(x, problem_.model.volume.triangles);
    const double wanted = problem_.target_volume_m3[static_cast<std::size_t>(k)];
    volume_sq_ += (v - wanted) * (v - wanted);
    mean_volume_ += wanted;
  }
  const std::vector<double> sizes = region_sizes(problem_, surface_);
  for (std::size_t r = 0; r < sizes.size(); ++r) error_.size[r].push_back(sizes[r]);
}

PlaybackError ErrorMeter::result(bool diverged) const {
  PlaybackError e = error_;
  if (diverged || !std::isfinite(sq_)) {
    e.diverged = true;
    e.rms_pct_of_motion = e.rms_pct_of_diagonal = e.max_pct_of_diagonal = e.volume_percent = e.mean_offset_pct_of_motion =
        std::numeric_limits<double>::infinity();
    for (auto& r : e.regions) r.rms_pct_of_motion = std::numeric_limits<double>::infinity();
    return e;
  }
  const Problem& problem = problem_;
  const double to_percent = 100.0 / problem.model.rest_extent_m;
  const double samples = double(problem.measure_steps) * double(problem.surface_rest.cols());
  const double rms_m = std::sqrt(sq_ / samples);
  e.rms_pct_of_diagonal = rms_m * to_percent;
  e.rms_pct_of_motion = share_of(rms_m, problem.target_motion_m);
  e.max_pct_of_diagonal = std::sqrt(max_sq_) * to_percent;
  if (error_sum_.cols() > 0) {
    const double offset_m = (error_sum_ / problem.measure_steps).colwise().squaredNorm().mean();
    e.mean_offset_pct_of_motion = share_of(std::sqrt(offset_m), problem.target_motion_m);
  }
  if (mean_volume_ > 0) {
    const double mean_volume = mean_volume_ / problem.measure_steps;
    e.volume_percent = std::sqrt(volume_sq_ / problem.measure_steps) / mean_volume * 100.0;
  }
  const double t0 = problem.measure_start_s() + problem.dt_s;
  for (std::size_t r = 0; r < problem.model.regions.size(); ++r) {
    // A region the target hardly moves (a thousandth of the organ's motion) has no motion
    // to be a share of: NaN, which the report shows as "-".
    if (region_count_[r] > 0 && problem.target_region_motion_m[r] < 1e-3 * problem.target_motion_m) {
      e.regions[r].rms_pct_of_motion = std::numeric_limits<double>::quiet_NaN();
    } else if (region_count_[r] > 0) {
      e.regions[r].rms_pct_of_motion =
          share_of(std::sqrt(region_sq_[r] / region_count_[r]), problem.target_region_motion_m[r]);
    }
    const double played = first_harmonic_phase(e.size[r], t0, problem.dt_s, problem.rate_hz);
    const double wanted = first_harmonic_phase(problem.target_size[r], t0, problem.dt_s, problem.rate_hz);
    e.regions[r].phase_deg = std::remainder(played - wanted, 2.0 * std::numbers::pi) * 180.0 / std::numbers::pi;
  }
  return e;
}

PlaybackError play(const Problem& problem, const sim::Model& model) {
  ErrorMeter meter(problem);
  world::BodyPlayback playback(model, problem.dt_s);
  playback.run(problem.settle_steps, [&](int k) {
    if (k == problem.settle_steps - 1) meter.watch(playback.state());
  });
  if (sim::diagnose(model, playback.state())) return meter.result(true);
  playback.run(problem.measure_steps, [&](int k) { meter.add(k, playback.state()); });
  return meter.result(sim::diagnose(model, playback.state()).has_value());
}

sim::Model with_regions(const sim::Model& base, const std::vector<scene::Region>& regions) {
  return sim::with_regions(base, sim::region_params(regions));
}

}  // namespace systole::train
