#include "export/morph.h"

#include <algorithm>
#include <cstdio>

#include <Eigen/Eigenvalues>

#include "common/error.h"
#include "mesh/normals.h"
#include "sim/motion_error.h"

namespace systole::exporter {
namespace {

/// Error of the animation's keys against the frames they encode (the closing key of a loop
/// is frame 0 again and adds nothing).
double key_error_pct(const MorphAnimation& morph, const OrganTrack& organ) {
  sim::Trajectory shapes;
  for (std::size_t f = 0; f < organ.frames_m.size(); ++f) shapes.push_back(shape_at_key(morph, static_cast<int>(f)));
  return sim::error_pct_of_motion(shapes, organ.frames_m);
}

std::string frame_name(int f) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d", f);
  return name;
}

Eigen::Matrix3Xf normalized_columns(const Eigen::Matrix3Xd& v) {
  Eigen::Matrix3Xf out(3, v.cols());
  for (Eigen::Index i = 0; i < v.cols(); ++i) {
    const double n = v.col(i).norm();
    out.col(i) = (n > 0 ? Eigen::Vector3d(v.col(i) / n) : Eigen::Vector3d(0, 0, 1)).cast<float>();
  }
  return out;
}

/// The principal components of the columns of d (displacements from their mean), largest
/// first, by the snapshot method: the Gram matrix is frames x frames, small beside 3n x 3n.
/// Each eigenvector's sign is fixed (largest entry positive) so the bytes do not depend on
/// what the solver happened to return; components without variance are left out.
struct Components {
  std::vector<Eigen::VectorXd> vectors;  ///< Over the frames, unit length.
  std::vector<double> values;            ///< Their eigenvalues (squared singular values). unit: m^2
};
Components principal_components(const Eigen::MatrixXd& d) {
  const Eigen::MatrixXd gram = d.transpose() * d;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  Components out;
  for (Eigen::Index i = gram.rows() - 1; i >= 0; --i) {
    if (!(eigen.eigenvalues()(i) > 0)) break;
    Eigen::VectorXd e = eigen.eigenvectors().col(i);
    Eigen::Index at = 0;
    e.cwiseAbs().maxCoeff(&at);
    if (e(at) < 0) e = -e;
    out.vectors.push_back(e);
    out.values.push_back(eigen.eigenvalues()(i));
  }
  return out;
}

}  // namespace

Eigen::Matrix3Xf vertex_normals(const OrganTrack& organ, const Eigen::Matrix3Xd& positions_m) {
  Eigen::Matrix3Xf normals(3, positions_m.cols());
  mesh::vertex_normals(positions_m.data(), static_cast<int>(positions_m.cols()), organ.triangles, normals.data());
  return normals;
}

Eigen::Matrix3Xd shape_at_key(const MorphAnimation& morph, int key) {
  Eigen::Matrix3Xd x = morph.base_position_m.cast<double>();
  for (int k = 0; k < morph.target_count(); ++k) {
    const float w = morph.weights(key, k);
    if (w != 0) x += double(w) * morph.position_delta_m[static_cast<std::size_t>(k)].cast<double>();
  }
  return x;
}

MorphAnimation frames_morph(const OrganTrack& organ, const Recording& rec) {
  MorphAnimation m;
  const int frames = static_cast<int>(organ.frames_m.size());
  m.base_position_m = organ.rest_m.cast<float>();
  m.base_normal = vertex_normals(organ, organ.rest_m);
  for (int f = 0; f < frames; ++f) {
    const auto& x = organ.frames_m[static_cast<std::size_t>(f)];
    // The delta from the stored (float) base, so base + delta lands on the frame to float rounding.
    m.position_delta_m.push_back((x - m.base_position_m.cast<double>()).cast<float>());
    m.normal_delta.push_back(vertex_normals(organ, x) - m.base_normal);
    m.target_names.push_back(frame_name(f));
  }
  const int keys = frames + (rec.loop ? 1 : 0);
  m.weights = Eigen::MatrixXf::Zero(keys, frames);
  for (int k = 0; k < keys; ++k) {
    m.key_times_s.push_back(static_cast<float>(k / rec.fps));
    m.weights(k, k % frames) = 1;
  }
  m.motion_m = sim::rms_motion_m(organ.frames_m);
  m.error_pct = key_error_pct(m, organ);
  return m;
}

namespace {

/// The compact loop's start: the organ's rest as the base, as a shape key's basis is, and the
/// loop's mean shape as a first target held at weight 1 over every key. A reader (a viewer, an
/// animator's tool, `systole tune`) then finds the organ's own rest in the file, not a pose.
MorphAnimation mean_over_rest(const OrganTrack& organ, const Eigen::VectorXd& mean, const Eigen::Matrix3Xf& mean_normal,
                              int frames) {
  MorphAnimation m;
  m.base_position_m = organ.rest_m.cast<float>();
  m.base_normal = vertex_normals(organ, organ.rest_m);
  m.position_delta_m.push_back((mean.reshaped(3, organ.rest_m.cols()) - m.base_position_m.cast<double>()).cast<float>());
  m.normal_delta.push_back(mean_normal - m.base_normal);
  m.target_names.push_back("mean");
  m.weights = Eigen::MatrixXf::Ones(frames + 1, 1);
  return m;
}

}  // namespace

MorphAnimation compact_morph(const OrganTrack& organ, const Recording& rec, const CompactOptions& options) {
  if (!rec.loop) {
    throw Error(ExitCode::kUsage, "the compact encoding needs the clip as a loop of whole cycles (output.loop)");
  }
  const int frames = static_cast<int>(organ.frames_m.size());
  const Eigen::Index n3 = 3 * organ.rest_m.cols();
  // The frames as columns of displacement from their mean.
  Eigen::MatrixXd d(n3, frames);
  for (int f = 0; f < frames; ++f) d.col(f) = organ.frames_m[static_cast<std::size_t>(f)].reshaped();
  const Eigen::VectorXd mean = d.rowwise().mean();
  d.colwise() -= mean;
  const Components pca = principal_components(d);
  const auto& v = pca.vectors;
  const auto& lambda = pca.values;
  // Normals: a shared unit base, and per component the least-squares fit of the normal
  // changes to its weight curve (the curves are orthogonal, so each fits alone).
  Eigen::MatrixXd normal_change(n3, frames);
  Eigen::Matrix3Xd normal_sum = Eigen::Matrix3Xd::Zero(3, organ.rest_m.cols());
  for (int f = 0; f < frames; ++f) {
    const Eigen::Matrix3Xd nf = vertex_normals(organ, organ.frames_m[static_cast<std::size_t>(f)]).cast<double>();
    normal_change.col(f) = nf.reshaped();
    normal_sum += nf;
  }
  const Eigen::Matrix3Xf base_normal = normalized_columns(normal_sum);
  normal_change.colwise() -= Eigen::VectorXd(base_normal.cast<double>().reshaped());

  const int available = static_cast<int>(v.size());
  MorphAnimation best;
  for (int k = std::min(options.min_targets, available); k <= std::min(options.max_targets, available); ++k) {
    MorphAnimation m = mean_over_rest(organ, mean, base_normal, frames);
    for (int c = 0; c < k; ++c) {
      const double s = std::sqrt(lambda[static_cast<std::size_t>(c)]);
      const Eigen::VectorXd component = d * v[static_cast<std::size_t>(c)] / s;  // unit length
      const Eigen::VectorXd curve = v[static_cast<std::size_t>(c)] * s;          // weight per frame
      m.position_delta_m.push_back(component.reshaped(3, organ.rest_m.cols()).cast<float>());
      const Eigen::VectorXd normal_fit = normal_change * curve / curve.squaredNorm();
      m.normal_delta.push_back(normal_fit.reshaped(3, organ.rest_m.cols()).cast<float>());
      m.target_names.push_back("mode_" + std::to_string(c + 1));
      m.weights.conservativeResize(Eigen::NoChange, c + 2);
      for (int f = 0; f < frames; ++f) m.weights(f, c + 1) = static_cast<float>(curve(f));
      m.weights(frames, c + 1) = m.weights(0, c + 1);  // The loop closes on its first shape, exactly.
    }
    for (int key = 0; key <= frames; ++key) m.key_times_s.push_back(static_cast<float>(key / rec.fps));
    m.motion_m = sim::rms_motion_m(organ.frames_m);
    m.error_pct = key_error_pct(m, organ);
    best = std::move(m);
    if (best.error_pct <= options.max_error_pct) return best;
  }
  if (available < options.min_targets) return best;  // Fewer distinct shapes than targets: exact already.
  char text[256];
  std::snprintf(text, sizeof text,
                "%s: %d morph targets of motion (beside the mean shape's) reproduce the loop within %.2f %% of the motion, over the budget of %.2f %%; "
                "raise --max-error or export every frame (--encoding frames)",
                organ.name.c_str(), best.target_count() - 1, best.error_pct, options.max_error_pct);
  throw Error(ExitCode::kDataError, text);
}

}  // namespace systole::exporter
