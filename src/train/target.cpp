#include "train/target.h"

#include <Eigen/Geometry>
#include <cmath>

#include "common/error.h"
#include "common/spline.h"
#include "mesh/animation.h"
#include "mesh/import.h"
#include "mesh/procedural.h"

namespace systole::train {

TargetMotion::TargetMotion(std::vector<double> phases, std::vector<Eigen::Matrix3Xd> poses)
    : phases_(std::move(phases)), poses_(std::move(poses)) {}

void TargetMotion::positions(double u, Eigen::Matrix3Xd& out) const {
  const std::size_t n = phases_.size();
  u -= std::floor(u);
  // The segment [phase_i, phase_i+1) holding u, wrapping past the last key to the first.
  std::size_t i = n - 1;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (u >= phases_[k] && u < phases_[k + 1]) i = k;
  }
  if (u < phases_[0]) i = n - 1;
  const std::size_t j = (i + 1) % n;
  double span = phases_[j] - phases_[i];
  if (span <= 0) span += 1.0;
  double local = u - phases_[i];
  if (local < 0) local += 1.0;
  const double f = local / span;
  // Uniform Catmull-Rom: smooth, passes through every key.
  out = catmull_rom(poses_[(i + n - 1) % n], poses_[i], poses_[j], poses_[(j + 1) % n], f);
}

namespace {

Eigen::Matrix3Xd to_matrix(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Matrix3Xd m(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = points[i];
  return m;
}

/// The organ's transform without its translation: what a displacement goes through.
Eigen::Matrix3d linear_part(const scene::Organ& organ) {
  const auto& t = organ.transform;
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(t.rotate_rad.z(), Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(t.rotate_rad.y(), Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(t.rotate_rad.x(), Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  return rotation * (t.scale * organ.mesh.unit_m);
}

/// The organ's mesh as its file or generator gives it, before centring and transform.
std::vector<Eigen::Vector3d> undeformed_vertices(const scene::Organ& organ) {
  return organ.mesh.file.empty() ? mesh::generate_organ(organ.mesh.procedural, organ.mesh.detail).surface.positions
                                 : mesh::import_mesh(organ.mesh.file).surface.positions;
}

TargetMotion from_frames(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  const Eigen::Matrix3Xd rest = to_matrix(geometry.mesh.surface.positions);
  const Eigen::Matrix3Xd undeformed = to_matrix(undeformed_vertices(organ));
  const Eigen::Matrix3d linear = linear_part(organ);
  std::vector<double> phases;
  std::vector<Eigen::Matrix3Xd> poses;
  for (const scene::TargetFrame& f : organ.target.frames) {
    const Eigen::Matrix3Xd frame = to_matrix(mesh::import_mesh(f.file).surface.positions);
    if (frame.cols() != rest.cols()) {
      throw Error(ExitCode::kDataError, f.file + ": key frame of organ '" + organ.name + "' has " + std::to_string(frame.cols()) +
                                            " vertices after welding; the organ has " + std::to_string(rest.cols()) +
                                            " (frames need the organ's vertices in the same order)");
    }
    poses.push_back(rest + linear * (frame - undeformed));
    phases.push_back(f.time_s * organ.target.rate_hz);
  }
  return TargetMotion(std::move(phases), std::move(poses));
}

TargetMotion from_animation(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  const Eigen::Matrix3Xd rest = to_matrix(geometry.mesh.surface.positions);
  const std::vector<Eigen::Vector3d> undeformed = undeformed_vertices(organ);
  if (undeformed.size() != static_cast<std::size_t>(rest.cols())) {
    throw Error(ExitCode::kInternal, "organ '" + organ.name + "': its mesh changed size between reads");
  }
  mesh::AnimationPoses animation = mesh::import_animation(organ.target.animation, undeformed, organ.target.animation_samples);
  const Eigen::Matrix3Xd from = to_matrix(undeformed);
  const Eigen::Matrix3d linear = linear_part(organ);
  std::vector<Eigen::Matrix3Xd> poses;
  for (const auto& pose : animation.poses) poses.push_back(rest + linear * (to_matrix(pose) - from));
  return TargetMotion(std::move(animation.phases), std::move(poses));
}

TargetMotion from_curves(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  const Eigen::Matrix3Xd rest = to_matrix(geometry.mesh.surface.positions);
  std::size_t keys = 0;
  for (const auto& c : organ.target.curves) keys = std::max(keys, c.samples.size());
  std::vector<double> phases;
  std::vector<Eigen::Matrix3Xd> poses;
  for (std::size_t k = 0; k < keys; ++k) {
    const double u = double(k) / double(keys);
    Eigen::Matrix3Xd pose = rest;
    for (const auto& c : organ.target.curves) {
      int region = 0;
      while (organ.regions[region].name != c.region) ++region;
      // The curve's own samples, read periodically at this key's phase (linear between samples).
      const double x = u * double(c.samples.size());
      const std::size_t i = static_cast<std::size_t>(x) % c.samples.size();
      const double f = x - std::floor(x);
      const double value = (1 - f) * c.samples[i] + f * c.samples[(i + 1) % c.samples.size()];
      const double scale = c.volume ? std::cbrt(value) : value;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      int count = 0;
      for (Eigen::Index v = 0; v < rest.cols(); ++v) {
        if (geometry.vertex_region[v] == region) centroid += rest.col(v), ++count;
      }
      centroid /= double(count);
      for (Eigen::Index v = 0; v < rest.cols(); ++v) {
        if (geometry.vertex_region[v] == region) pose.col(v) = centroid + scale * (rest.col(v) - centroid);
      }
    }
    phases.push_back(u);
    poses.push_back(std::move(pose));
  }
  return TargetMotion(std::move(phases), std::move(poses));
}

}  // namespace

TargetMotion load_target(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  if (!organ.target.enabled) throw Error(ExitCode::kDataError, "organ '" + organ.name + "' has no target");
  if (!organ.target.animation.empty()) return from_animation(organ, geometry);
  return organ.target.frames.empty() ? from_curves(organ, geometry) : from_frames(organ, geometry);
}

}  // namespace systole::train
