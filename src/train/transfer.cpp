#include "train/transfer.h"

#include <nanoflann.hpp>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

#include "common/error.h"
#include "sim/contact/geometry.h"
#include "sim/motion_error.h"

namespace systole::train {
namespace {

/// Points (3 x n) under a nanoflann k-d tree: nearest neighbours in O(log n).
class PointIndex {
 public:
  explicit PointIndex(Eigen::Matrix3Xd points)
      : cloud_{std::move(points)}, tree_(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
    tree_.buildIndex();
  }
  /// Up to k nearest points' columns, nearest first.
  std::vector<std::size_t> nearest(const Eigen::Vector3d& p, std::size_t k) const {
    k = std::min<std::size_t>(k, static_cast<std::size_t>(cloud_.points.cols()));
    std::vector<std::size_t> index(k);
    std::vector<double> distance(k);
    const std::size_t found = tree_.knnSearch(p.data(), k, index.data(), distance.data());
    index.resize(found);
    return index;
  }
  double distance(const Eigen::Vector3d& p) const {
    const auto i = nearest(p, 1);
    return i.empty() ? std::numeric_limits<double>::infinity() : (cloud_.points.col(static_cast<Eigen::Index>(i[0])) - p).norm();
  }
  const Eigen::Matrix3Xd& points() const { return cloud_.points; }

 private:
  struct Cloud {  // nanoflann's dataset adaptor.
    Eigen::Matrix3Xd points;
    std::size_t kdtree_get_point_count() const { return static_cast<std::size_t>(points.cols()); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return points(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(i)); }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3, std::size_t>;
  Cloud cloud_;
  Tree tree_;
};

/// Some of a surface's triangles (those with an area) under a k-d tree of their corners:
/// the closest point of them to a point, searched among the triangles round its `k` nearest
/// corners (exact for surfaces that are not much coarser than the distance to them, which is
/// what alignment and binding ask).
class SurfaceIndex {
 public:
  /// Over `subset` of the triangles (their indices), or every triangle when it is null.
  SurfaceIndex(const Eigen::Matrix3Xd& positions, const std::vector<Eigen::Vector3i>& triangles, std::size_t k,
               const std::vector<int>* subset = nullptr)
      : positions_(positions), triangles_(triangles), k_(k) {
    std::map<int, std::size_t> slot;  // Corner -> its column in the tree.
    auto add = [&](int t) {
      const Eigen::Vector3i& c = triangles[static_cast<std::size_t>(t)];
      if ((positions.col(c[1]) - positions.col(c[0])).cross(positions.col(c[2]) - positions.col(c[0])).norm() <= 0) return;
      for (int j = 0; j < 3; ++j) {
        const auto [at, added] = slot.emplace(c[j], slot.size());
        if (added) incident_.emplace_back();
        incident_[at->second].push_back(t);
      }
    };
    if (subset) {
      for (int t : *subset) add(t);
    } else {
      for (std::size_t t = 0; t < triangles.size(); ++t) add(static_cast<int>(t));
    }
    Eigen::Matrix3Xd corners(3, static_cast<Eigen::Index>(slot.size()));
    for (const auto& [vertex, column] : slot) corners.col(static_cast<Eigen::Index>(column)) = positions.col(vertex);
    corners_ = std::make_unique<PointIndex>(std::move(corners));
  }
  struct Hit {
    int triangle = -1;  ///< -1: no triangle indexed.
    Eigen::Vector3d bary = Eigen::Vector3d::Zero();
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double distance = std::numeric_limits<double>::infinity();
  };
  Hit closest(const Eigen::Vector3d& p) const {
    Hit best;
    if (incident_.empty()) return best;
    for (std::size_t i : corners_->nearest(p, k_)) {
      for (int t : incident_[i]) {
        const Eigen::Vector3i& c = triangles_[static_cast<std::size_t>(t)];
        const auto cp = sim::contact::closest_on_triangle(p, positions_.col(c[0]), positions_.col(c[1]), positions_.col(c[2]));
        const Eigen::Vector3d q = cp.bary[0] * positions_.col(c[0]) + cp.bary[1] * positions_.col(c[1]) + cp.bary[2] * positions_.col(c[2]);
        const double d = (p - q).norm();
        if (d < best.distance || (d == best.distance && t < best.triangle)) best = {t, cp.bary, q, d};
      }
    }
    return best;
  }

 private:
  const Eigen::Matrix3Xd& positions_;
  const std::vector<Eigen::Vector3i>& triangles_;
  std::size_t k_;
  std::vector<std::vector<int>> incident_;  ///< Per indexed corner, its triangles.
  std::unique_ptr<PointIndex> corners_;
};

double diagonal(const Eigen::Matrix3Xd& p) { return (p.rowwise().maxCoeff() - p.rowwise().minCoeff()).norm(); }

/// Every `stride`-th column, so alignment costs the same on a big mesh as on a small one.
Eigen::Matrix3Xd sample(const Eigen::Matrix3Xd& p, Eigen::Index most = 1000) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (p.cols() + most - 1) / most);
  Eigen::Matrix3Xd out(3, (p.cols() + stride - 1) / stride);
  for (Eigen::Index i = 0, j = 0; i < p.cols(); i += stride, ++j) out.col(j) = p.col(i);
  return out;
}

struct Fit {
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  Eigen::Matrix3Xd apply(const Eigen::Matrix3Xd& p) const { return (linear * p).colwise() + offset; }
};

/// The RMS of both ways' surface distances between `target` placed by `fit` and the organ:
/// every target sample's to the organ's surface, every organ sample's to the placed target's
/// (found in the target's own frame, through the inverse map: nearest is kept by a
/// similarity, and nearly so by an affine map near one; the target's index is built once).
double misfit(const SurfaceIndex& target, const Eigen::Matrix3Xd& target_sample, const Fit& fit, const SurfaceIndex& organ,
              const Eigen::Matrix3Xd& organ_sample) {
  const Eigen::Matrix3Xd placed_sample = fit.apply(target_sample);
  const Eigen::Matrix3d inverse = fit.linear.inverse();
  double sum = 0;
  for (Eigen::Index i = 0; i < placed_sample.cols(); ++i) sum += std::pow(organ.closest(placed_sample.col(i)).distance, 2);
  for (Eigen::Index i = 0; i < organ_sample.cols(); ++i) {
    const auto hit = target.closest(inverse * (organ_sample.col(i) - fit.offset));
    sum += (fit.linear * hit.point + fit.offset - organ_sample.col(i)).squaredNorm();
  }
  return std::sqrt(sum / double(placed_sample.cols() + organ_sample.cols()));
}

/// Iterative closest points from `fit`: pairs both ways (every target sample with its closest
/// point of the organ's surface, every organ sample with its closest point of the placed
/// target's, taken back to the target's frame by its weights), then the best similarity
/// (Umeyama 1991, Eigen::umeyama) or affine map of the pairs; 40 rounds or until the map
/// stops moving.
Fit closest_points(const SurfaceIndex& target, const Eigen::Matrix3Xd& target_sample, const SurfaceIndex& organ,
                   const Eigen::Matrix3Xd& organ_sample, Fit fit, bool affine, double size) {
  for (int round = 0; round < 40; ++round) {
    const Eigen::Matrix3Xd placed_sample = fit.apply(target_sample);
    const Eigen::Matrix3d inverse = fit.linear.inverse();
    Eigen::Matrix3Xd from(3, target_sample.cols() + organ_sample.cols()), to(3, from.cols());
    for (Eigen::Index i = 0; i < target_sample.cols(); ++i) {
      from.col(i) = target_sample.col(i);
      to.col(i) = organ.closest(placed_sample.col(i)).point;
    }
    for (Eigen::Index j = 0; j < organ_sample.cols(); ++j) {
      from.col(target_sample.cols() + j) = target.closest(inverse * (organ_sample.col(j) - fit.offset)).point;
      to.col(target_sample.cols() + j) = organ_sample.col(j);
    }
    Fit next;
    if (affine && round >= 20) {  // The similarity first: an affine map from a poor start shears.
      Eigen::MatrixXd a(from.cols(), 4);
      a.leftCols<3>() = from.transpose();
      a.col(3).setOnes();
      const Eigen::MatrixXd solution = a.colPivHouseholderQr().solve(Eigen::MatrixXd(to.transpose()));  // 4 x 3
      next.linear = solution.topRows<3>().transpose();
      next.offset = solution.row(3).transpose();
    } else {
      const Eigen::Matrix4d m = Eigen::umeyama(from, to, true);
      next.linear = m.topLeftCorner<3, 3>();
      next.offset = m.topRightCorner<3, 1>();
    }
    const double moved = (next.apply(target_sample) - placed_sample).colwise().norm().maxCoeff();
    fit = next;
    if (moved < 1e-6 * size && !(affine && round < 20)) break;
  }
  return fit;
}

/// Principal axes of points as a right-handed rotation's columns, and their centroid.
std::pair<Eigen::Matrix3d, Eigen::Vector3d> principal_axes(const Eigen::Matrix3Xd& p) {
  const Eigen::Vector3d centroid = p.rowwise().mean();
  const Eigen::Matrix3Xd centred = p.colwise() - centroid;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred * centred.transpose());
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(0) *= -1;
  return {axes, centroid};
}

/// The principal axes of `target` turned onto `organ`'s: centroids on each other, sizes by
/// the RMS radius, the four right-handed pairings of the axes.
std::vector<Fit> axes_pairings(const Eigen::Matrix3Xd& target, const Eigen::Matrix3Xd& organ) {
  const auto [organ_axes, organ_centre] = principal_axes(organ);
  const auto [target_axes, target_centre] = principal_axes(target);
  const double ratio = std::sqrt((organ.colwise() - organ_centre).squaredNorm() / double(organ.cols()) /
                                 std::max(1e-300, (target.colwise() - target_centre).squaredNorm() / double(target.cols())));
  std::vector<Fit> out;
  for (const Eigen::Vector3d flip : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(-1, 1, -1),
                                     Eigen::Vector3d(1, -1, -1)}) {
    Fit f;
    f.linear = ratio * organ_axes * flip.asDiagonal() * target_axes.transpose();
    f.offset = organ_centre - f.linear * target_centre;
    out.push_back(f);
  }
  return out;
}

/// Throws when `a` leaves the surfaces too far apart or sizes them unlike the units (align).
void refuse_if_apart(const Alignment& a, const RestSurface& target, const RestSurface& organ, const std::string& what) {
  std::ostringstream figures;
  figures.precision(3);
  if (a.misfit > kMaxMisfit) {
    figures << what << ": the target's surface cannot be laid on the organ's: the best alignment (" << a.how
            << ") leaves them " << 100 * a.misfit << " % of the organ's size apart (RMS of the surface distances both ways; at most "
            << 100 * kMaxMisfit << " %), comparing the target's " << target.positions.cols() << " rest vertices with the organ's "
            << organ.positions.cols() << " surface vertices. Is it the same organ? Give target.align.landmarks (3 or more "
            << "pairs of matching points) to start the alignment";
    throw Error(ExitCode::kDataError, figures.str());
  }
  if (a.scale_vs_placed > 2 || a.scale_vs_placed < 0.5) {
    figures << what << ": the target is " << a.scale_vs_placed << " times the organ's size once aligned (" << a.how
            << "): its file is in other units than the organ's mesh; give target.units";
    throw Error(ExitCode::kDataError, figures.str());
  }
}

}  // namespace

Alignment align(const RestSurface& target, const RestSurface& organ, const AlignOptions& options, const std::string& what) {
  const double size = diagonal(organ.positions);
  const SurfaceIndex organ_index(organ.positions, organ.triangles, 8), target_index(target.positions, target.triangles, 8);
  const Eigen::Matrix3Xd organ_sample = sample(organ.positions), target_sample = sample(target.positions);
  const bool affine = options.mode == AlignOptions::Mode::kAffine;
  auto score = [&](const Fit& f) { return misfit(target_index, target_sample, f, organ_index, organ_sample) / size; };

  struct Tried {
    Fit fit;
    double misfit;
    std::string how;
  };
  std::vector<Tried> starts;
  const Fit placed{options.placed_linear, options.placed_offset};
  starts.push_back({placed, score(placed), "as placed (the organ's units and transform)"});
  starts.push_back({Fit{}, score(Fit{}), "as it is (the scene's frame)"});
  if (options.landmarks.size() >= 3) {
    Eigen::Matrix3Xd from(3, options.landmarks.size()), to(3, options.landmarks.size());
    for (std::size_t i = 0; i < options.landmarks.size(); ++i) {
      from.col(static_cast<Eigen::Index>(i)) = options.landmarks[i].first;
      to.col(static_cast<Eigen::Index>(i)) = options.landmarks[i].second;
    }
    const Eigen::Matrix4d m = Eigen::umeyama(from, to, true);
    const Fit by_landmarks{m.topLeftCorner<3, 3>(), m.topRightCorner<3, 1>()};
    starts.push_back({by_landmarks, score(by_landmarks), "the landmarks"});
  }
  // Starts for closest points: the above, and the principal axes matched.
  std::vector<Tried> tried;
  for (const Fit& f : axes_pairings(target.positions, organ.positions)) starts.push_back({f, score(f), "principal axes"});
  for (const Tried& s : starts) {
    const Fit f = closest_points(target_index, target_sample, organ_index, organ_sample, s.fit, affine, size);
    tried.push_back({f, score(f), s.how + " + closest points (" + (affine ? "affine" : "rigid and scale") + ")"});
  }
  const Tried& moved = *std::min_element(tried.begin(), tried.end(), [](const Tried& a, const Tried& b) { return a.misfit < b.misfit; });
  // Where its file puts it, a target is kept unless moving it explains most of its misfit:
  // its rest shape may differ from the organ's for real (a clip's mean pose, a kidney sagged
  // on its pedicle), and an alignment would move that real difference away as if it were a
  // misplacement. A misplaced file (other origin, other units) is far off and moves close.
  const Tried* best = &moved;
  for (const Tried& s : starts) {
    const bool kept = s.how.rfind("as ", 0) == 0 && s.misfit < std::max(kPlacedClose, kKeptUnlessMovedCloser * moved.misfit);
    if (kept && (best == &moved || s.misfit < best->misfit)) best = &s;
  }
  Alignment out{best->fit.linear, best->fit.offset, best->misfit, 1.0, best->how};
  const double placed_scale = std::cbrt(std::abs(options.placed_linear.determinant()));
  out.scale_vs_placed = std::cbrt(std::abs(best->fit.linear.determinant())) / std::max(1e-300, placed_scale);
  refuse_if_apart(out, target, organ, what);
  return out;
}

namespace {

bool same_part(const std::string& a, const std::string& b) {
  auto last = [](const std::string& s) { return s.substr(s.rfind('/') + 1); };
  return a == b || last(a) == b || a == last(b);
}

/// A triangle's frame at positions p: first edge, in-plane normal to it, face normal.
Eigen::Matrix3d frame(const Eigen::Matrix3Xd& p, const Eigen::Vector3i& t) {
  const Eigen::Vector3d e1 = p.col(t[1]) - p.col(t[0]), e2 = p.col(t[2]) - p.col(t[0]);
  Eigen::Matrix3d f;
  f.col(0) = e1.normalized();
  f.col(2) = e1.cross(e2).normalized();
  f.col(1) = f.col(2).cross(f.col(0));
  return f;
}

}  // namespace

SurfaceBinding::SurfaceBinding(const RestSurface& from, const RestSurface& to) {
  // Per part of `from` (a triangle's part is its first corner's) and "" for all: its surface.
  std::map<std::string, std::vector<int>> part_triangles;
  if (!from.vertex_part_name.empty()) {
    for (std::size_t t = 0; t < from.triangles.size(); ++t) {
      const std::string& name = from.vertex_part_name[static_cast<std::size_t>(from.triangles[t][0])];
      if (!name.empty()) part_triangles[name].push_back(static_cast<int>(t));
    }
  }
  std::map<std::string, std::unique_ptr<SurfaceIndex>> parts;
  parts[""] = std::make_unique<SurfaceIndex>(from.positions, from.triangles, 16);
  for (const auto& [name, triangles] : part_triangles) parts[name] = std::make_unique<SurfaceIndex>(from.positions, from.triangles, 16, &triangles);
  // Which of `from`'s parts each of `to`'s part names binds to ("" every part).
  std::map<std::string, const SurfaceIndex*> part_for;
  auto surface_for = [&](const std::string& name) {
    auto found = part_for.find(name);
    if (found != part_for.end()) return found->second;
    const SurfaceIndex* match = parts.at("").get();
    for (const auto& [candidate, index] : part_triangles) {
      if (!name.empty() && same_part(candidate, name)) match = parts.at(candidate).get();
    }
    return part_for.emplace(name, match).first->second;
  };
  const auto n = static_cast<std::size_t>(to.positions.cols());
  corners_.resize(n);
  bary_.resize(n);
  offset_.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const Eigen::Vector3d p = to.positions.col(static_cast<Eigen::Index>(v));
    const auto hit = surface_for(to.vertex_part_name.empty() ? std::string() : to.vertex_part_name[v])->closest(p);
    if (hit.triangle < 0) throw Error(ExitCode::kDataError, "the target's surface has no triangle with an area near vertex " + std::to_string(v));
    corners_[v] = from.triangles[static_cast<std::size_t>(hit.triangle)];
    bary_[v] = hit.bary;
    offset_[v] = frame(from.positions, corners_[v]).transpose() * (p - hit.point);
    largest_gap_ = std::max(largest_gap_, hit.distance);
  }
}

void SurfaceBinding::apply(const Eigen::Matrix3Xd& from_pose, Eigen::Matrix3Xd& out) const {
  out.resize(3, static_cast<Eigen::Index>(corners_.size()));
  for (std::size_t v = 0; v < corners_.size(); ++v) {
    const Eigen::Vector3i& c = corners_[v];
    Eigen::Vector3d p = bary_[v][0] * from_pose.col(c[0]) + bary_[v][1] * from_pose.col(c[1]) + bary_[v][2] * from_pose.col(c[2]);
    if (!offset_[v].isZero(0)) p += frame(from_pose, c) * offset_[v];
    out.col(static_cast<Eigen::Index>(v)) = p;
  }
}

double transfer_loss_pct(const RestSurface& target, const std::vector<Eigen::Matrix3Xd>& target_poses, const RestSurface& organ,
                         const std::vector<Eigen::Matrix3Xd>& organ_poses) {
  const SurfaceBinding back(organ, target);
  Eigen::Matrix3Xd replayed, at_rest;
  back.apply(organ.positions, at_rest);
  double sum = 0;
  for (std::size_t k = 0; k < target_poses.size(); ++k) {
    back.apply(organ_poses[k], replayed);
    sum += ((replayed - at_rest) - (target_poses[k] - target.positions)).squaredNorm();
  }
  const double error = std::sqrt(sum / double(target_poses.size() * static_cast<std::size_t>(target.positions.cols())));
  const double motion = sim::rms_motion_m(target_poses);
  return motion > 0 ? 100.0 * error / motion : 0.0;
}

}  // namespace systole::train
