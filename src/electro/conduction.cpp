#include "electro/conduction.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "common/error.h"

namespace systole::electro {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kNever = std::numeric_limits<double>::infinity();

/// The myocardium's nodes sorted into the pathway's places.
struct Places {
  std::vector<Tissue> tissue;
  std::vector<char> septal;        ///< In the interventricular septum.
  std::vector<char> lv_lining;     ///< The left ventricle's endocardium.
  std::vector<char> rv_lining;     ///< The right ventricle's.
};

bool in_part(const mesh::OrganMesh& mesh, int node, int part) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  if (part < 0) return false;
  if (m.node_part[static_cast<std::size_t>(node)] == part) return true;
  return std::any_of(m.node_also_in.begin(), m.node_also_in.end(),
                     [&](const std::pair<int, int>& p) { return p.first == node && p.second == part; });
}

/// Walls 0 and 1 are the left and right hearts (mesh/anatomy.h): ventricle up to the
/// annulus, atrium above it; the vessels' walls are not excitable. The right ventricle's
/// lining includes the septum's right face, which is the left wall's outside there.
Places sort_nodes(const mesh::OrganMesh& mesh) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  const std::size_t n = m.nodes.size();
  const int septum = mesh.part_index("interventricular_septum");
  Places p{std::vector<Tissue>(n, Tissue::kNone), std::vector<char>(n, 0), std::vector<char>(n, 0),
           std::vector<char>(n, 0)};
  for (std::size_t i = 0; i < n; ++i) {
    const int wall = m.node_wall[i];
    if (wall > 1) continue;
    const bool ventricle = m.node_along[i] <= m.annulus_along + 1e-9;
    p.tissue[i] = ventricle ? Tissue::kVentricle : Tissue::kAtrium;
    if (!ventricle) continue;
    p.septal[i] = in_part(mesh, static_cast<int>(i), septum);
    const bool lining = m.node_depth[i] < 1e-9, outside = m.node_depth[i] > 1 - 1e-9;
    if (wall == 0 && lining) p.lv_lining[i] = 1;
    if ((wall == 1 && lining) || (wall == 0 && outside && p.septal[i])) p.rv_lining[i] = 1;
  }
  return p;
}

/// The node of `among` nearest `x`, or -1 when none is.
int nearest(const mesh::Myocardium& m, const Eigen::Vector3d& x, const std::vector<char>& among) {
  int best = -1;
  double best_m = kNever;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (!among[i]) continue;
    const double d = (m.nodes[i] - x).norm();
    if (d < best_m) best = static_cast<int>(i), best_m = d;
  }
  return best;
}

/// The node of `among` whose place along the meridian is nearest `along`, ties to the lowest index.
int nearest_along(const mesh::Myocardium& m, double along, const std::vector<char>& among) {
  int best = -1;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (among[i] && (best < 0 || std::abs(m.node_along[i] - along) < std::abs(m.node_along[best] - along)))
      best = static_cast<int>(i);
  }
  return best;
}

std::vector<char> where(std::size_t n, const std::function<bool(std::size_t)>& test) {
  std::vector<char> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = test(i);
  return out;
}

struct Edge {
  int to;
  double s;  ///< Travel time. unit: s
};

/// The graph the excitation travels: every spring between two nodes of one tissue, each
/// taking its length over the speed along it. The Purkinje layer is fast and isotropic; the
/// ventricles' muscle is faster along the fibres (the spring's fibre share, the squared
/// cosine of its angle with them: the speed on the ellipse of the two speeds).
std::vector<std::vector<Edge>> conduction_graph(const mesh::Myocardium& m, const Places& places,
                                                const std::vector<char>& purkinje, const ConductionParams& params) {
  std::vector<std::vector<Edge>> graph(m.nodes.size());
  for (std::size_t j = 0; j < m.springs.size(); ++j) {
    const auto [a, b] = m.springs[j];
    const Tissue ta = places.tissue[static_cast<std::size_t>(a)], tb = places.tissue[static_cast<std::size_t>(b)];
    if (ta == Tissue::kNone || ta != tb) continue;  // The fibrous ring insulates atria from ventricles.
    double speed = params.atrial_mps;
    if (ta == Tissue::kVentricle) {
      const bool same_layer = purkinje[static_cast<std::size_t>(a)] && purkinje[static_cast<std::size_t>(b)] &&
                              places.lv_lining[static_cast<std::size_t>(a)] == places.lv_lining[static_cast<std::size_t>(b)];
      const double f = std::max(0.0, m.fibre_share[j]);
      speed = same_layer ? params.purkinje_mps
                         : std::sqrt(f * params.fibre_mps * params.fibre_mps +
                                     (1 - f) * params.cross_fibre_mps * params.cross_fibre_mps);
    }
    const double s = (m.nodes[static_cast<std::size_t>(a)] - m.nodes[static_cast<std::size_t>(b)]).norm() / speed;
    graph[static_cast<std::size_t>(a)].push_back({b, s});
    graph[static_cast<std::size_t>(b)].push_back({a, s});
  }
  return graph;
}

/// Dijkstra's ordered front from the seeded nodes (seed time already in `time`).
void spread(const std::vector<std::vector<Edge>>& graph, std::vector<double>& time) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> front;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < kNever) front.emplace(time[i], static_cast<int>(i));
  }
  while (!front.empty()) {
    const auto [t, node] = front.top();
    front.pop();
    if (t > time[static_cast<std::size_t>(node)]) continue;
    for (const Edge& e : graph[static_cast<std::size_t>(node)]) {
      if (t + e.s < time[static_cast<std::size_t>(e.to)]) {
        time[static_cast<std::size_t>(e.to)] = t + e.s;
        front.emplace(t + e.s, e.to);
      }
    }
  }
}

int require(int node, const char* what) {
  if (node < 0) throw Error(ExitCode::kDataError, std::string("the conduction system found no ") + what + " in the myocardium");
  return node;
}

/// Action-potential duration at a 1-s cycle: atria 200 ms; ventricles 210 ms at the apical
/// epicardium, 60 ms longer at the endocardium (the transmural gradient, Drouin et al. 1995,
/// J Am Coll Cardiol 26:185) and 50 ms longer at the base (the apex's are shorter,
/// Szentadrassy et al. 2005, Cardiovasc Res 65:851): the epicardium and the apex, excited
/// last across and along the wall, recover first, so the T wave follows the QRS. The
/// figures are set so the computed QT is normal (docs/electrophysiology.md).
double duration_1s(const mesh::Myocardium& m, Tissue tissue, std::size_t i) {
  if (tissue == Tissue::kAtrium) return 0.200;
  const double to_base = std::clamp(m.node_along[i] / m.annulus_along, 0.0, 1.0);
  return 0.210 + 0.060 * (1 - m.node_depth[i]) + 0.050 * to_base;
}


/// The atria from the sinus node (the right atrium where the superior vena cava enters it),
/// Bachmann's bundle a fast path to the left atrium's nearest wall; into `time`.
void excite_atria(const mesh::OrganMesh& mesh, const Places& places, const ConductionParams& params, Excitation& ex,
                  std::vector<double>& time) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  const std::size_t n = m.nodes.size();
  const auto atrium_of = [&](int wall) {
    return where(n, [&](std::size_t i) { return places.tissue[i] == Tissue::kAtrium && m.node_wall[i] == wall; });
  };
  const int svc = mesh.part_index("superior_vena_cava");
  Eigen::Vector3d svc_centre = Eigen::Vector3d::Zero();
  int svc_nodes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (m.node_part[i] == svc) svc_centre += m.nodes[i], ++svc_nodes;
  }
  if (svc_nodes == 0) throw Error(ExitCode::kDataError, "the conduction system found no superior vena cava");
  ex.sinus_node = require(nearest(m, svc_centre / svc_nodes, atrium_of(1)), "right atrium");
  time[static_cast<std::size_t>(ex.sinus_node)] = 0;
  const Eigen::Vector3d& sinus = m.nodes[static_cast<std::size_t>(ex.sinus_node)];
  const int bachmann = require(nearest(m, sinus, atrium_of(0)), "left atrium");
  time[static_cast<std::size_t>(bachmann)] = (m.nodes[static_cast<std::size_t>(bachmann)] - sinus).norm() / params.bachmann_mps;
  spread(conduction_graph(m, places, std::vector<char>(n, 0), params), time);
  // The AV node and the His bundle: the septum's crest, just below the right atrium's floor.
  const std::vector<char> septal_rv = where(n, [&](std::size_t i) { return places.septal[i] && places.rv_lining[i]; });
  ex.his_node = require(nearest_along(m, m.annulus_along, septal_rv), "interventricular septum");
  ex.av_node = require(nearest(m, m.nodes[static_cast<std::size_t>(ex.his_node)], atrium_of(1)), "AV node");
  ex.av_node_s = time[static_cast<std::size_t>(ex.av_node)];
  ex.his_s = ex.av_node_s + params.av_node_s;
}

/// The ventricles from the His bundle: the bundle branches reach the left septum's middle
/// and the right's apical third (the moderator band), then their ventricle's Purkinje
/// layer; a blocked branch does neither. Into `time` (the ventricles' entries).
void excite_ventricles(const mesh::Myocardium& m, const Places& places, const ConductionParams& params,
                       const Excitation& ex, std::vector<double>& time) {
  const std::size_t n = m.nodes.size();
  const double reach = params.purkinje_reach * m.annulus_along;
  std::vector<char> purkinje(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool left = places.lv_lining[i] && params.block != Block::kLeftBundle;
    const bool right = places.rv_lining[i] && !places.lv_lining[i] && params.block != Block::kRightBundle;
    purkinje[i] = (left || right) && m.node_along[i] <= reach;
  }
  const Eigen::Vector3d& his = m.nodes[static_cast<std::size_t>(ex.his_node)];
  const auto enter = [&](int entry) {
    time[static_cast<std::size_t>(entry)] = ex.his_s + (m.nodes[static_cast<std::size_t>(entry)] - his).norm() / params.bundle_mps;
  };
  const auto septal = [&](const std::vector<char>& lining) {
    return where(n, [&](std::size_t i) { return places.septal[i] && lining[i]; });
  };
  if (params.block != Block::kLeftBundle)
    enter(require(nearest_along(m, 0.55 * m.annulus_along, septal(places.lv_lining)), "left septal wall"));
  if (params.block != Block::kRightBundle) {
    // The right branch runs down the septum and crosses the moderator band to the free
    // wall's lining: both ends are reached together.
    const int wall = require(nearest_along(m, 0.35 * m.annulus_along, septal(places.rv_lining)), "right septal wall");
    enter(wall);
    enter(require(nearest(m, m.nodes[static_cast<std::size_t>(wall)],
                          where(n, [&](std::size_t i) { return places.rv_lining[i] && m.node_wall[i] == 1; })),
                  "right ventricle's lining"));
  }
  spread(conduction_graph(m, places, purkinje, params), time);
}

}  // namespace

Excitation excite(const mesh::OrganMesh& mesh, const ConductionParams& params) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  if (m.empty() || m.node_wall.size() != m.nodes.size())
    throw Error(ExitCode::kDataError, "a conduction system needs the generated heart's myocardium");
  const std::size_t n = m.nodes.size();
  const Places places = sort_nodes(mesh);
  Excitation ex;
  ex.tissue = places.tissue;
  std::vector<double> atria(n, kNever), ventricles(n, kNever);
  excite_atria(mesh, places, params, ex, atria);
  excite_ventricles(m, places, params, ex, ventricles);
  ex.activation_s.assign(n, kNaN);
  ex.duration_1s_s.assign(n, kNaN);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = places.tissue[i] == Tissue::kVentricle ? ventricles[i] : atria[i];
    if (places.tissue[i] == Tissue::kNone || t == kNever) continue;
    ex.activation_s[i] = t;
    ex.duration_1s_s[i] = duration_1s(m, places.tissue[i], i);
  }
  return ex;
}

double action_potential_s(double duration_1s_s, double cycle_s) { return duration_1s_s * std::cbrt(cycle_s); }

}  // namespace systole::electro
