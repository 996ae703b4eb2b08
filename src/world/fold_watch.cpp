#include "world/fold_watch.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace systole::world {
namespace {

Eigen::Vector3d normal_of(const Eigen::Vector3i& t, const auto& position) {
  const Eigen::Vector3d n = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

}  // namespace

FoldWatch::FoldWatch(const scene::Organ& organ, const mesh::OrganGeometry& geometry) : organ_(organ.name) {
  const auto& surface = geometry.mesh.surface;
  // Regions worth watching: driven and free to move.
  std::vector<int> watched_index(organ.regions.size(), -1);
  for (std::size_t r = 0; r < organ.regions.size(); ++r) {
    const scene::Region& region = organ.regions[r];
    if (region.pinned || region.drive.waveform == scene::Waveform::kNone || region.drive.rate_hz <= 0) continue;
    watched_index[r] = static_cast<int>(regions_.size());
    regions_.push_back({region.name, 1.0 / region.drive.rate_hz, {}, -1});
  }
  if (regions_.empty()) return;
  // Pairs of triangles sharing an edge whose two ends are in the same watched region; only
  // the triangles of some pair are kept (`kept`: surface triangle -> index in triangles_).
  std::map<std::pair<int, int>, int> first_triangle_of_edge;
  std::vector<int> kept(surface.triangles.size(), -1);
  const auto keep = [&](int t) {
    if (kept[static_cast<std::size_t>(t)] < 0) {
      kept[static_cast<std::size_t>(t)] = static_cast<int>(triangles_.size());
      triangles_.push_back(surface.triangles[static_cast<std::size_t>(t)]);
    }
    return kept[static_cast<std::size_t>(t)];
  };
  const auto rest = [&](int v) { return surface.positions[static_cast<std::size_t>(v)]; };
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
    const Eigen::Vector3i& tri = surface.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      const int region = geometry.vertex_region[static_cast<std::size_t>(a)];
      if (region < 0 || region != geometry.vertex_region[static_cast<std::size_t>(b)]) continue;
      const int watched = watched_index[static_cast<std::size_t>(region)];
      if (watched < 0) continue;
      const auto [it, inserted] = first_triangle_of_edge.emplace(std::minmax(a, b), t);
      if (inserted) continue;
      regions_[static_cast<std::size_t>(watched)].pairs.push_back(static_cast<int>(pairs_.size()));
      pairs_.emplace_back(keep(it->second), keep(t));
      // Folded: turned more than kFoldAngle past the rest angle, that is (cos falling on
      // [0, pi]) a cosine below the rest angle's plus kFoldAngle (never, past pi): no acos a frame.
      const double limit = angle_between(normal_of(surface.triangles[static_cast<std::size_t>(it->second)], rest),
                                         normal_of(tri, rest)) +
                           kFoldAngle_rad;
      folded_below_cos_.push_back(limit < M_PI ? std::cos(limit) : -2.0);
    }
  }
  std::erase_if(regions_, [](const Region& r) { return r.pairs.empty(); });
  shares_.assign(regions_.size(), 0.0);
  normals_.resize(triangles_.size());
  double fastest_s = regions_.empty() ? 0 : regions_.front().period_s;
  for (const Region& r : regions_) fastest_s = std::min(fastest_s, r.period_s);
  look_every_s_ = fastest_s / kLooksPerCycle;
}

std::optional<std::string> FoldWatch::update(const Eigen::Matrix3Xd& positions, double time_s) {
  if (regions_.empty()) return std::nullopt;
  // A little early rather than a frame late when the frames do not divide the period.
  next_look_s_ = time_s + 0.99 * look_every_s_;
  const auto at = [&](int v) { return Eigen::Vector3d(positions.col(v)); };
  // A triangle borders up to three pairs: its normal once.
  for (std::size_t t = 0; t < triangles_.size(); ++t) normals_[t] = normal_of(triangles_[t], at);
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    Region& region = regions_[r];
    int folded = 0;
    for (const int p : region.pairs) {
      const Eigen::Vector2i& pair = pairs_[static_cast<std::size_t>(p)];
      const double cos_angle = normals_[static_cast<std::size_t>(pair[0])].dot(normals_[static_cast<std::size_t>(pair[1])]);
      folded += cos_angle < folded_below_cos_[static_cast<std::size_t>(p)];
    }
    shares_[r] = double(folded) / region.pairs.size();
    if (shares_[r] <= kFoldedShare) {
      region.crumpled_since_s = -1;
      continue;
    }
    if (region.crumpled_since_s < 0) region.crumpled_since_s = time_s;
    if (time_s - region.crumpled_since_s > region.period_s) {
      char text[512];
      std::snprintf(text, sizeof text,
                    "region '%s' of '%s' is crumpling: %.0f%% of its surface has folded by more than 60 degrees "
                    "from its rest shape, for longer than a cycle of its drive (%.2f s)",
                    region.name.c_str(), organ_.c_str(), 100 * shares_[r], region.period_s);
      return std::string(text);
    }
  }
  return std::nullopt;
}

}  // namespace systole::world
