#include "mesh/anatomy.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace systole::mesh {
namespace {

template <typename At>
double enclosed_volume(const Cavity& cavity, const At& at) {
  double six_volume = 0;  // Facing into the blood, the lining encloses negative volume.
  for (const Eigen::Vector3i& t : cavity.lining) six_volume += at(t[0]).dot(at(t[1]).cross(at(t[2])));
  for (const std::vector<int>& rim : cavity.rims) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : rim) centre += at(v);
    centre /= static_cast<double>(rim.size());
    for (std::size_t i = 0; i < rim.size(); ++i) six_volume += at(rim[i]).dot(at(rim[(i + 1) % rim.size()]).cross(centre));
  }
  return -six_volume / 6.0;
}

}  // namespace

void find_rims(Cavity& cavity) {
  // Directed edges used once are the rims; a lining edge (a, b) gives the cap (b, a, centre),
  // so each rim is walked from b to a.
  std::map<std::pair<int, int>, int> edges;
  for (const Eigen::Vector3i& t : cavity.lining) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  std::map<int, int> next;
  for (const auto& [edge, count] : edges) {
    if (!edges.count({edge.second, edge.first})) next[edge.second] = edge.first;
  }
  cavity.rims.clear();
  std::map<int, bool> walked;
  for (const auto& [start, unused] : next) {
    if (walked[start]) continue;
    std::vector<int> rim;
    for (int v = start; !walked[v]; v = next.count(v) ? next[v] : start) {
      walked[v] = true;
      rim.push_back(v);
    }
    cavity.rims.push_back(std::move(rim));
  }
}

namespace {

/// A triangle as its corners in order, whichever corner it is listed from.
std::array<int, 3> corners(const Eigen::Vector3i& t) {
  std::array<int, 3> c{t[0], t[1], t[2]};
  std::sort(c.begin(), c.end());
  return c;
}

}  // namespace

std::vector<Eigen::Vector3i> epicardium(const Anatomy& anatomy) {
  std::set<std::array<int, 3>> lining;
  for (const Cavity& cavity : anatomy.cavities) {
    for (const Eigen::Vector3i& t : cavity.lining) lining.insert(corners(t));
  }
  std::vector<Eigen::Vector3i> out;
  for (const Eigen::Vector3i& t : anatomy.muscle) {
    if (!lining.count(corners(t))) out.push_back(t);
  }
  return out;
}

std::vector<int> lining_vertices(const Anatomy& anatomy) {
  std::set<int> outside;
  for (const Eigen::Vector3i& t : epicardium(anatomy)) outside.insert({t[0], t[1], t[2]});
  std::set<int> lining;
  for (const Cavity& cavity : anatomy.cavities) {
    for (const Eigen::Vector3i& t : cavity.lining) {
      for (int k = 0; k < 3; ++k) {
        if (!outside.count(t[k])) lining.insert(t[k]);
      }
    }
  }
  return {lining.begin(), lining.end()};
}

double cavity_volume(const Cavity& cavity, const std::vector<Eigen::Vector3d>& positions) {
  return enclosed_volume(cavity, [&](int v) -> const Eigen::Vector3d& { return positions[v]; });
}

double cavity_volume(const Cavity& cavity, const Eigen::Matrix3Xd& positions) {
  return enclosed_volume(cavity, [&](int v) -> Eigen::Vector3d { return positions.col(v); });
}

}  // namespace systole::mesh
