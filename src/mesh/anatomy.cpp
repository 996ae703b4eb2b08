#include "mesh/anatomy.h"

#include <Eigen/Geometry>
#include <map>

namespace systole::mesh {
namespace {

template <typename At>
double enclosed_volume(const Cavity& cavity, const At& at) {
  // Directed edges used once: the open rims. Each rim loop is capped by a fan about its
  // centroid, turned like the lining (edge (a, b) of the lining gives cap triangle (b, a, c)).
  std::map<std::pair<int, int>, int> edges;
  for (const Eigen::Vector3i& t : cavity.lining) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  std::map<int, int> rim_next;  // b -> a for every rim edge (a, b): walks the cap's way round.
  for (const auto& [edge, count] : edges) {
    if (!edges.count({edge.second, edge.first})) rim_next[edge.second] = edge.first;
  }
  double six_volume = 0;  // Facing into the blood, the lining encloses negative volume.
  auto add = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    six_volume += a.dot(b.cross(c));
  };
  for (const Eigen::Vector3i& t : cavity.lining) add(at(t[0]), at(t[1]), at(t[2]));
  std::map<int, bool> capped;
  for (const auto& [start, unused] : rim_next) {
    if (capped[start]) continue;
    std::vector<int> loop;
    for (int v = start; !capped[v]; v = rim_next.count(v) ? rim_next[v] : start) {
      capped[v] = true;
      loop.push_back(v);
    }
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : loop) centre += at(v);
    centre /= static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) add(at(loop[i]), at(loop[(i + 1) % loop.size()]), centre);
  }
  return -six_volume / 6.0;
}

}  // namespace

double cavity_volume(const Cavity& cavity, const std::vector<Eigen::Vector3d>& positions) {
  return enclosed_volume(cavity, [&](int v) -> const Eigen::Vector3d& { return positions[v]; });
}

double cavity_volume(const Cavity& cavity, const Eigen::Matrix3Xd& positions) {
  return enclosed_volume(cavity, [&](int v) -> Eigen::Vector3d { return positions.col(v); });
}

}  // namespace systole::mesh
