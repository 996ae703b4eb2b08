#include "train/target.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "common/error.h"
#include "common/spline.h"
#include "mesh/animation.h"
#include "mesh/import.h"
#include "mesh/gltf_read.h"
#include "mesh/point_cache_read.h"
#include "mesh/procedural.h"
#include "mesh/vtu_read.h"
#include "train/transfer.h"

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

/// The organ's placement of a file in its mesh's frame: rest = linear * file + offset (the
/// offset from the undeformed vertices: the centring the organ's import applied).
std::pair<Eigen::Matrix3d, Eigen::Vector3d> placement(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  const Eigen::Matrix3d linear = linear_part(organ);
  // The file in its own units (target.units) where they are not the organ mesh's.
  const Eigen::Matrix3d file_linear = organ.target.unit_m > 0 ? Eigen::Matrix3d(linear * (organ.target.unit_m / organ.mesh.unit_m)) : linear;
  const Eigen::Matrix3Xd rest = to_matrix(geometry.mesh.surface.positions);
  const Eigen::Matrix3Xd undeformed = to_matrix(undeformed_vertices(organ));
  if (undeformed.cols() != rest.cols()) return {file_linear, Eigen::Vector3d::Zero()};
  return {file_linear, (rest - linear * undeformed).rowwise().mean()};
}

train::RestSurface organ_surface(const mesh::OrganGeometry& geometry) {
  RestSurface s{to_matrix(geometry.mesh.surface.positions), geometry.mesh.surface.triangles, {}};
  const mesh::OrganMesh& m = geometry.mesh;
  if (!m.part_names.empty()) {
    for (int part : m.vertex_part) s.vertex_part_name.push_back(part >= 0 ? m.part_names[static_cast<std::size_t>(part)] : "");
  }
  return s;
}

/// Which of the file's periods is the target: the one at the time training measures (after
/// `settle` cycles), so a clip of many beats is compared at the same moment of its run (an
/// organ that still settles - a kidney sagging on its pedicle - has not yet the shape of its
/// last beat); its last period when it holds fewer.
int compared_period(const scene::Target& t) {
  return std::min(static_cast<int>(std::floor(t.settle_cycles + 1e-9)), t.cycles - 1);
}

/// The target's file, by its extension: a point cache with its OBJ, a ParaView series, or
/// anything assimp reads (sampled `samples` times over its last period).
mesh::AnimatedSurface read_target_file(const scene::Organ& organ) {
  const scene::Target& t = organ.target;
  std::string extension = std::filesystem::path(t.animation).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".pc2" || extension == ".mdd") return mesh::read_point_cache(t.animation);
  if (extension == ".pvd") return mesh::read_vtu_series(t.animation, t.piece);
  if (extension == ".glb" || extension == ".gltf") {
    if (auto morphs = mesh::read_gltf_morphs(t.animation, t.animation_samples, t.cycles, compared_period(t))) return *morphs;
  }
  return mesh::read_animated_file(t.animation, t.animation_samples, t.cycles, compared_period(t));
}

TargetMotion from_animation(const scene::Organ& organ, const mesh::OrganGeometry& geometry) {
  const int cycles = organ.target.cycles;
  mesh::AnimatedSurface file = read_target_file(organ);
  // Phases: the poses of the compared period spread over one period, whatever its length.
  const double span = file.duration / cycles, start = span * compared_period(organ.target);
  std::vector<double> phases;
  std::vector<std::vector<Eigen::Vector3d>> kept;
  for (std::size_t k = 0; k < file.times.size(); ++k) {
    const double u = (file.times[k] - start) / span;
    if (u < -1e-9 || u >= 1 - 1e-9) continue;
    phases.push_back(std::max(0.0, u));
    kept.push_back(std::move(file.poses[k]));
  }
  file.poses = std::move(kept);
  if (phases.size() < 4) {
    throw Error(ExitCode::kDataError, file.file + ": the target's period " + std::to_string(compared_period(organ.target) + 1) + " (of " + std::to_string(cycles) + ", target.cycles) holds " +
                                          std::to_string(phases.size()) + " poses; it needs at least 4");
  }

  RestSurface target{to_matrix(file.rest), file.triangles, {}};
  if (!file.parts.empty()) {
    for (int part : file.vertex_part) target.vertex_part_name.push_back(part >= 0 ? file.parts[static_cast<std::size_t>(part)] : "");
  }
  const RestSurface organ_rest = organ_surface(geometry);
  AlignOptions options;
  std::tie(options.placed_linear, options.placed_offset) = placement(organ, geometry);
  if (organ.target.align.affine) options.mode = AlignOptions::Mode::kAffine;
  for (const scene::TargetLandmark& l : organ.target.align.landmarks) options.landmarks.push_back({l.target, l.organ_m});
  const std::string what = file.file + " (the target of organ '" + organ.name + "')";
  const Alignment alignment = align(target, organ_rest, options, what);
  RestSurface aligned = target;
  aligned.positions = (alignment.linear * target.positions).colwise() + alignment.offset;

  const SurfaceBinding binding(aligned, organ_rest);
  std::vector<Eigen::Matrix3Xd> target_poses, poses;
  for (const auto& p : file.poses) {
    target_poses.push_back((alignment.linear * to_matrix(p)).colwise() + alignment.offset);
    Eigen::Matrix3Xd organ_pose;
    binding.apply(target_poses.back(), organ_pose);
    poses.push_back(std::move(organ_pose));
  }
  const double loss = transfer_loss_pct(aligned, target_poses, organ_rest, poses);
  TargetMotion motion(std::move(phases), std::move(poses));
  std::ostringstream note;
  note.precision(3);
  note << "The target " << file.file << " (" << target.positions.cols() << " vertices, " << file.poses.size()
       << " poses) was laid on the organ's " << organ_rest.positions.cols() << " surface vertices " << alignment.how
       << ", " << 100 * alignment.misfit << " % of the organ's size apart at rest; each organ vertex follows the nearest point "
       << "of the target's surface (at most " << 1e3 * binding.largest_gap() << " mm away). The transfer loses " << loss
       << " % of the target's motion (its vertices replayed from the organ's surface, against its own motion).";
  motion.set_transfer_note(note.str());
  return motion;
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
