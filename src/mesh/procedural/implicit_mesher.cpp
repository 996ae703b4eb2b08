#include "mesh/procedural/implicit_mesher.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

#include "common/error.h"

namespace systole::mesh::procedural {
namespace {

using Vec = Eigen::Vector3d;
using Face = std::array<int, 3>;
constexpr int kDead = -1;

// ---------------------------------------------------------------------------------------
// Connectivity of a closed manifold triangle mesh, rebuilt after each batch of edits.

struct Edge {
  int face0, slot0;  // face0 walks F[face0][slot0] -> F[face0][slot0 + 1].
  int face1, slot1;  // face1 walks the same edge the other way.
};

struct Topology {
  std::vector<int> start, faces;  // CSR: faces around each vertex.
  std::vector<Edge> edges;

  int valence(int v) const { return start[static_cast<size_t>(v) + 1] - start[static_cast<size_t>(v)]; }
};

Topology build_topology(const std::vector<Face>& F, int vertex_count) {
  Topology topo;
  topo.start.assign(static_cast<size_t>(vertex_count) + 1, 0);
  for (const Face& f : F) {
    if (f[0] == kDead) continue;
    for (int v : f) ++topo.start[static_cast<size_t>(v) + 1];
  }
  for (int v = 0; v < vertex_count; ++v) topo.start[static_cast<size_t>(v) + 1] += topo.start[static_cast<size_t>(v)];
  topo.faces.resize(static_cast<size_t>(topo.start.back()));
  std::vector<int> fill(topo.start.begin(), topo.start.end() - 1);
  for (int f = 0; f < static_cast<int>(F.size()); ++f) {
    if (F[static_cast<size_t>(f)][0] == kDead) continue;
    for (int v : F[static_cast<size_t>(f)]) topo.faces[static_cast<size_t>(fill[static_cast<size_t>(v)]++)] = f;
  }
  // Each undirected edge once, from the face that walks it from the lower index.
  for (int f = 0; f < static_cast<int>(F.size()); ++f) {
    const Face& face = F[static_cast<size_t>(f)];
    if (face[0] == kDead) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = face[static_cast<size_t>(k)], b = face[static_cast<size_t>((k + 1) % 3)];
      if (a > b) continue;
      int twin = -1, twin_slot = -1, matches = 0;
      for (int i = topo.start[static_cast<size_t>(b)]; i < topo.start[static_cast<size_t>(b) + 1]; ++i) {
        const int g = topo.faces[static_cast<size_t>(i)];
        const Face& other = F[static_cast<size_t>(g)];
        for (int j = 0; j < 3; ++j) {
          if (other[static_cast<size_t>(j)] == b && other[static_cast<size_t>((j + 1) % 3)] == a) {
            twin = g, twin_slot = j, ++matches;
          }
        }
      }
      if (matches != 1) throw Error(ExitCode::kInternal, "procedural mesher: the surface lost its manifold structure");
      topo.edges.push_back({f, k, twin, twin_slot});
    }
  }
  return topo;
}

// ---------------------------------------------------------------------------------------
// The surface as a function over directions: each vertex is a unit direction u from the
// centre, and its position is where the ray along u leaves the surface. For a surface
// that is star-shaped about the centre this is a homeomorphism from the sphere, so a
// triangulation whose spherical triangles all keep their orientation is an embedded,
// closed, outward-facing surface, whatever the remeshing does to it.

class RaySurface {
 public:
  RaySurface(const Field& field, const Vec& center, double radius) : field_(field), center_(center), radius_(radius) {}

  /// Distance from the centre to the outermost crossing along `u`; `hint` (or < 0) is a
  /// nearby previous answer to start from. unit: m
  double cast(const Vec& u, double hint) const {
    double outside = radius_;
    if (hint > 0) {  // Start just outside the hint if that is outside the surface.
      const double t = std::min(radius_, hint * 1.03 + radius_ * 1e-3);
      if (field_.distance(at(u, t)) > 0) outside = t;
    }
    // Sphere tracing inwards: the field hardly overstates the distance, so steps of 0.8 d
    // cannot jump over a thin part.
    double inside = -1;
    double d_out = field_.distance(at(u, outside));
    for (int i = 0; i < 10000; ++i) {
      const double t = outside - std::max(0.8 * d_out, radius_ * 2e-4);
      const double d = t > 0 ? field_.distance(at(u, t)) : -1;
      if (d < 0) {
        inside = std::max(t, 0.0);
        break;
      }
      outside = t, d_out = d;
    }
    if (inside < 0) throw Error(ExitCode::kInternal, "procedural mesher: a ray from the centre found no surface");
    // Illinois false position between the last outside and the first inside point.
    double d_in = field_.distance(at(u, inside));
    int side = 0;
    for (int i = 0; i < 60 && outside - inside > radius_ * 1e-12; ++i) {
      const double t = inside + (outside - inside) * (d_in / (d_in - d_out));
      const double d = field_.distance(at(u, t));
      if (d < 0) {
        inside = t, d_in = d;
        if (side == -1) d_out *= 0.5;
        side = -1;
      } else {
        outside = t, d_out = d;
        if (side == 1) d_in *= 0.5;
        side = 1;
      }
      if (std::abs(d) < radius_ * 1e-12) return t;
    }
    return 0.5 * (inside + outside);
  }

  Vec at(const Vec& u, double t) const { return center_ + t * u; }

 private:
  const Field& field_;
  Vec center_;
  double radius_;
};

struct Vertices {
  std::vector<Vec> dir;    // Unit direction from the centre.
  std::vector<double> t;   // Distance along it. unit: m
  std::vector<Vec> pos;    // center + t * dir. unit: m

  int add(const RaySurface& surface, const Vec& u, double hint) {
    const double r = surface.cast(u, hint);
    dir.push_back(u);
    t.push_back(r);
    pos.push_back(surface.at(u, r));
    return static_cast<int>(pos.size()) - 1;
  }
  void move(const RaySurface& surface, int v, const Vec& u) {
    const size_t i = static_cast<size_t>(v);
    t[i] = surface.cast(u, t[i]);
    dir[i] = u;
    pos[i] = surface.at(u, t[i]);
  }
  int size() const { return static_cast<int>(pos.size()); }
};

// Orientation of a spherical triangle: positive when counter-clockwise seen from outside.
double spherical_orientation(const Vec& a, const Vec& b, const Vec& c) { return a.dot(b.cross(c)); }

Vec face_normal(const std::vector<Vec>& P, int a, int b, int c) {
  return (P[static_cast<size_t>(b)] - P[static_cast<size_t>(a)]).cross(P[static_cast<size_t>(c)] - P[static_cast<size_t>(a)]);
}

double cos_between(const Vec& u, const Vec& v) {
  const double n = u.norm() * v.norm();
  return n > 0 ? u.dot(v) / n : -1.0;
}

double edge_length(const std::vector<Vec>& P, const std::vector<Face>& F, const Edge& edge) {
  const Face& f = F[static_cast<size_t>(edge.face0)];
  return (P[static_cast<size_t>(f[static_cast<size_t>(edge.slot0)])] -
          P[static_cast<size_t>(f[static_cast<size_t>((edge.slot0 + 1) % 3)])])
      .norm();
}

void remove_dead_faces(std::vector<Face>& F) {
  F.erase(std::remove_if(F.begin(), F.end(), [](const Face& f) { return f[0] == kDead; }), F.end());
}

// Vertices around v (the other corners of its faces), sorted, unique.
std::vector<int> ring(const Topology& topo, const std::vector<Face>& F, int v) {
  std::vector<int> out;
  for (int i = topo.start[static_cast<size_t>(v)]; i < topo.start[static_cast<size_t>(v) + 1]; ++i) {
    for (int w : F[static_cast<size_t>(topo.faces[static_cast<size_t>(i)])]) {
      if (w != v) out.push_back(w);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Whether every face around the vertices `moved` stays positively oriented on the
// sphere when their directions become `dirs` (others unchanged), with a small margin.
bool keeps_orientation(const Topology& topo, const std::vector<Face>& F, const std::vector<Vec>& dir,
                       const std::vector<int>& moved, const std::vector<Vec>& dirs, int skip0 = -1, int skip1 = -1,
                       int merged_from = -1) {
  for (int v : moved) {
    for (int i = topo.start[static_cast<size_t>(v)]; i < topo.start[static_cast<size_t>(v) + 1]; ++i) {
      const int f = topo.faces[static_cast<size_t>(i)];
      if (f == skip0 || f == skip1) continue;
      Vec u[3];
      for (int k = 0; k < 3; ++k) {
        int w = F[static_cast<size_t>(f)][static_cast<size_t>(k)];
        if (w == merged_from) w = moved.front();
        u[k] = dir[static_cast<size_t>(w)];
        for (size_t m = 0; m < moved.size(); ++m) {
          if (w == moved[m]) u[k] = dirs[m];
        }
      }
      if (spherical_orientation(u[0], u[1], u[2]) <= 1e-14) return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// The start: an icosphere, each vertex cast onto the surface along its direction.

void icosphere(int levels, std::vector<Vec>& P, std::vector<Face>& F) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  P = {Vec(-1, t, 0), Vec(1, t, 0),  Vec(-1, -t, 0), Vec(1, -t, 0), Vec(0, -1, t), Vec(0, 1, t),
       Vec(0, -1, -t), Vec(0, 1, -t), Vec(t, 0, -1), Vec(t, 0, 1),  Vec(-t, 0, -1), Vec(-t, 0, 1)};
  for (Vec& p : P) p.normalize();
  F = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
       {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
       {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      P.push_back((P[static_cast<size_t>(a)] + P[static_cast<size_t>(b)]).normalized());
      return midpoint[key] = static_cast<int>(P.size()) - 1;
    };
    std::vector<Face> next;
    next.reserve(F.size() * 4);
    for (const Face& f : F) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    F = std::move(next);
  }
}

// ---------------------------------------------------------------------------------------
// Remeshing operations. Each batch edits faces that share nothing with another edit of
// the same batch, then the connectivity is rebuilt.

// Splits edges longer than `max_length` at the middle direction. Returns the count.
int split_long_edges(const RaySurface& surface, Vertices& V, std::vector<Face>& F, double max_length) {
  const Topology topo = build_topology(F, V.size());
  std::vector<std::pair<double, int>> candidates;
  for (int e = 0; e < static_cast<int>(topo.edges.size()); ++e) {
    const double length = edge_length(V.pos, F, topo.edges[static_cast<size_t>(e)]);
    if (length > max_length) candidates.emplace_back(-length, e);
  }
  std::sort(candidates.begin(), candidates.end());  // Longest first; ties by edge index.
  std::vector<char> touched(F.size(), 0);
  int splits = 0;
  for (const auto& [negative_length, e] : candidates) {
    const Edge edge = topo.edges[static_cast<size_t>(e)];
    if (touched[static_cast<size_t>(edge.face0)] || touched[static_cast<size_t>(edge.face1)]) continue;
    touched[static_cast<size_t>(edge.face0)] = touched[static_cast<size_t>(edge.face1)] = 1;
    const Face f0 = F[static_cast<size_t>(edge.face0)], f1 = F[static_cast<size_t>(edge.face1)];
    const int a = f0[static_cast<size_t>(edge.slot0)], b = f0[static_cast<size_t>((edge.slot0 + 1) % 3)];
    const int c = f0[static_cast<size_t>((edge.slot0 + 2) % 3)], d = f1[static_cast<size_t>((edge.slot1 + 2) % 3)];
    const Vec u = (V.dir[static_cast<size_t>(a)] + V.dir[static_cast<size_t>(b)]).normalized();
    const double r = surface.cast(u, 0.5 * (V.t[static_cast<size_t>(a)] + V.t[static_cast<size_t>(b)]));
    const Vec x = surface.at(u, r);
    // Across a jump of the ray distance (a shape not star-shaped about the centre) the
    // halves stay long: splitting would never end there.
    const double longest_half = std::max((x - V.pos[static_cast<size_t>(a)]).norm(), (x - V.pos[static_cast<size_t>(b)]).norm());
    if (longest_half > 0.9 * -negative_length) continue;
    const int m = V.add(surface, u, r);
    // (a,b,c) -> (a,m,c) + (m,b,c); (b,a,d) -> (b,m,d) + (m,a,d): orientation kept (the
    // middle of a great-circle arc keeps both spherical triangles positive).
    F[static_cast<size_t>(edge.face0)] = {a, m, c};
    F.push_back({m, b, c});
    F[static_cast<size_t>(edge.face1)] = {b, m, d};
    F.push_back({m, a, d});
    ++splits;
  }
  return splits;
}

// Collapses edges shorter than `min_length` into their middle direction, unless that
// breaks the link condition (a pinch), makes an edge longer than `max_length`, or turns
// a triangle over on the sphere. Returns the count.
int collapse_short_edges(const RaySurface& surface, Vertices& V, std::vector<Face>& F, double min_length,
                         double max_length) {
  const Topology topo = build_topology(F, V.size());
  std::vector<std::pair<double, int>> candidates;
  for (int e = 0; e < static_cast<int>(topo.edges.size()); ++e) {
    const double length = edge_length(V.pos, F, topo.edges[static_cast<size_t>(e)]);
    if (length < min_length) candidates.emplace_back(length, e);
  }
  std::sort(candidates.begin(), candidates.end());  // Shortest first.
  std::vector<char> locked(static_cast<size_t>(V.size()), 0);
  int collapses = 0;
  for (const auto& [length, e] : candidates) {
    const Edge edge = topo.edges[static_cast<size_t>(e)];
    const Face f0 = F[static_cast<size_t>(edge.face0)], f1 = F[static_cast<size_t>(edge.face1)];
    // An earlier collapse in this pass removed this edge's faces: its corners read kDead
    // (UBSan found locked[-1] through fuzz_scene; fuzz/regressions/scene/).
    if (f0[0] == kDead || f1[0] == kDead) continue;
    const int a = f0[static_cast<size_t>(edge.slot0)], b = f0[static_cast<size_t>((edge.slot0 + 1) % 3)];
    if (locked[static_cast<size_t>(a)] || locked[static_cast<size_t>(b)]) continue;
    const int c = f0[static_cast<size_t>((edge.slot0 + 2) % 3)], d = f1[static_cast<size_t>((edge.slot1 + 2) % 3)];
    // Link condition (Dey et al. 1999): a and b share exactly the two neighbours c and d.
    const std::vector<int> ring_a = ring(topo, F, a), ring_b = ring(topo, F, b);
    std::vector<int> common;
    std::set_intersection(ring_a.begin(), ring_a.end(), ring_b.begin(), ring_b.end(), std::back_inserter(common));
    if (common.size() != 2 || c == d || topo.valence(c) <= 3 || topo.valence(d) <= 3) continue;
    const Vec u = (V.dir[static_cast<size_t>(a)] + V.dir[static_cast<size_t>(b)]).normalized();
    if (!keeps_orientation(topo, F, V.dir, {a, b}, {u, u}, edge.face0, edge.face1)) continue;
    const double r = surface.cast(u, 0.5 * (V.t[static_cast<size_t>(a)] + V.t[static_cast<size_t>(b)]));
    const Vec m = surface.at(u, r);
    bool ok = true;
    for (const std::vector<int>* around : {&ring_a, &ring_b}) {
      for (int w : *around) ok = ok && (w == a || w == b || (V.pos[static_cast<size_t>(w)] - m).norm() <= max_length);
    }
    if (!ok) continue;
    for (int i = topo.start[static_cast<size_t>(b)]; i < topo.start[static_cast<size_t>(b) + 1]; ++i) {
      Face& face = F[static_cast<size_t>(topo.faces[static_cast<size_t>(i)])];
      for (int& w : face) w = (w == b) ? a : w;
    }
    F[static_cast<size_t>(edge.face0)] = {kDead, kDead, kDead};
    F[static_cast<size_t>(edge.face1)] = {kDead, kDead, kDead};
    V.dir[static_cast<size_t>(a)] = u, V.t[static_cast<size_t>(a)] = r, V.pos[static_cast<size_t>(a)] = m;
    for (const std::vector<int>* around : {&ring_a, &ring_b}) {
      for (int w : *around) locked[static_cast<size_t>(w)] = 1;
    }
    locked[static_cast<size_t>(a)] = locked[static_cast<size_t>(b)] = 1;
    ++collapses;
  }
  remove_dead_faces(F);
  return collapses;
}

// Flips edges where that brings the four corners' valences closer to 6 (the regular
// valence of a closed triangle mesh), or makes a much better-shaped pair. Returns the count.
int flip_edges(const Vertices& V, std::vector<Face>& F) {
  const Topology topo = build_topology(F, V.size());
  std::vector<int> valence(static_cast<size_t>(V.size()));
  for (int v = 0; v < V.size(); ++v) valence[static_cast<size_t>(v)] = topo.valence(v);
  std::vector<char> locked(static_cast<size_t>(V.size()), 0);
  const std::vector<Vec>& P = V.pos;
  auto min_angle_cos = [&](int a, int b, int c) {  // Largest cosine = smallest angle.
    const Vec& x = P[static_cast<size_t>(a)];
    const Vec& y = P[static_cast<size_t>(b)];
    const Vec& z = P[static_cast<size_t>(c)];
    return std::max({cos_between(y - x, z - x), cos_between(z - y, x - y), cos_between(x - z, y - z)});
  };
  int flips = 0;
  for (const Edge& edge : topo.edges) {
    const Face f0 = F[static_cast<size_t>(edge.face0)], f1 = F[static_cast<size_t>(edge.face1)];
    const int a = f0[static_cast<size_t>(edge.slot0)], b = f0[static_cast<size_t>((edge.slot0 + 1) % 3)];
    const int c = f0[static_cast<size_t>((edge.slot0 + 2) % 3)], d = f1[static_cast<size_t>((edge.slot1 + 2) % 3)];
    if (locked[static_cast<size_t>(a)] || locked[static_cast<size_t>(b)] || locked[static_cast<size_t>(c)] ||
        locked[static_cast<size_t>(d)] || c == d) {
      continue;
    }
    const int va = valence[static_cast<size_t>(a)], vb = valence[static_cast<size_t>(b)];
    const int vc = valence[static_cast<size_t>(c)], vd = valence[static_cast<size_t>(d)];
    if (va <= 3 || vb <= 3) continue;
    const int before = std::abs(va - 6) + std::abs(vb - 6) + std::abs(vc - 6) + std::abs(vd - 6);
    const int after = std::abs(va - 7) + std::abs(vb - 7) + std::abs(vc - 5) + std::abs(vd - 5);
    const double old_shape = std::max(min_angle_cos(a, b, c), min_angle_cos(b, a, d));
    const double new_shape = std::max(min_angle_cos(a, d, c), min_angle_cos(d, b, c));
    const bool better_valence = after < before && new_shape < 0.985;  // Not below ~10 degrees.
    const bool better_shape = after <= before + 2 && new_shape < old_shape - 0.05;
    if (!better_valence && !better_shape) continue;
    const Vec n0 = face_normal(P, a, b, c), n1 = face_normal(P, b, a, d);
    if (cos_between(n0, n1) < 0.5) continue;  // A crease: flipping would change the shape.
    const std::vector<Vec>& U = V.dir;
    if (spherical_orientation(U[static_cast<size_t>(a)], U[static_cast<size_t>(d)], U[static_cast<size_t>(c)]) <= 1e-14 ||
        spherical_orientation(U[static_cast<size_t>(d)], U[static_cast<size_t>(b)], U[static_cast<size_t>(c)]) <= 1e-14) {
      continue;
    }
    const std::vector<int> ring_c = ring(topo, F, c);
    if (std::binary_search(ring_c.begin(), ring_c.end(), d)) continue;  // c-d exists already.
    F[static_cast<size_t>(edge.face0)] = {a, d, c};
    F[static_cast<size_t>(edge.face1)] = {d, b, c};
    locked[static_cast<size_t>(a)] = locked[static_cast<size_t>(b)] = 1;
    locked[static_cast<size_t>(c)] = locked[static_cast<size_t>(d)] = 1;
    ++flips;
  }
  return flips;
}

// Moves each vertex towards the area-weighted centroid of its faces (Jacobi: all moves
// from the same old positions), back onto the surface along the centroid's direction;
// a move that would turn a spherical triangle over is halved, then dropped.
void relax(const RaySurface& surface, const Vec& center, Vertices& V, const std::vector<Face>& F, double weight) {
  const Topology topo = build_topology(F, V.size());
  std::vector<Vec> target(V.dir);
  for (int v = 0; v < V.size(); ++v) {
    if (topo.valence(v) == 0) continue;
    Vec centroid = Vec::Zero();
    double area = 0;
    for (int i = topo.start[static_cast<size_t>(v)]; i < topo.start[static_cast<size_t>(v) + 1]; ++i) {
      const Face& f = F[static_cast<size_t>(topo.faces[static_cast<size_t>(i)])];
      const double a = face_normal(V.pos, f[0], f[1], f[2]).norm();
      centroid += a * (V.pos[static_cast<size_t>(f[0])] + V.pos[static_cast<size_t>(f[1])] + V.pos[static_cast<size_t>(f[2])]) / 3.0;
      area += a;
    }
    if (area <= 0) continue;
    const Vec goal = V.pos[static_cast<size_t>(v)] + weight * (centroid / area - V.pos[static_cast<size_t>(v)]);
    target[static_cast<size_t>(v)] = (goal - center).normalized();
  }
  // Apply in index order against the current directions, so each check is exact.
  for (int v = 0; v < V.size(); ++v) {
    Vec u = target[static_cast<size_t>(v)];
    for (int attempt = 0; attempt < 3; ++attempt) {
      if (keeps_orientation(topo, F, V.dir, {v}, {u})) {
        V.move(surface, v, u);
        break;
      }
      u = (u + V.dir[static_cast<size_t>(v)]).normalized();
    }
  }
}

TriangleMesh compact(const std::vector<Vec>& P, const std::vector<Face>& F) {
  TriangleMesh mesh;
  std::vector<int> remap(P.size(), -1);
  for (const Face& f : F) {
    for (int v : f) remap[static_cast<size_t>(v)] = 0;
  }
  for (size_t v = 0; v < P.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = static_cast<int>(mesh.positions.size());
    mesh.positions.push_back(P[v]);
  }
  for (const Face& f : F) {
    mesh.triangles.emplace_back(remap[static_cast<size_t>(f[0])], remap[static_cast<size_t>(f[1])],
                                remap[static_cast<size_t>(f[2])]);
  }
  return mesh;
}

double surface_area(const std::vector<Vec>& P, const std::vector<Face>& F) {
  double area = 0;
  for (const Face& f : F) area += 0.5 * face_normal(P, f[0], f[1], f[2]).norm();
  return area;
}

}  // namespace

TriangleMesh mesh_implicit_surface(const Field& field, const MesherSettings& settings) {
  if (!(field.distance(settings.center) < 0)) {
    throw Error(ExitCode::kInternal, "procedural mesher: the centre is outside the surface");
  }
  const RaySurface surface(field, settings.center, settings.bound_radius);
  // Start near the target count; splits then put vertices where the area is.
  int levels = 1;
  while (20 * (1 << (2 * (levels + 1))) <= settings.target_triangles && levels < 7) ++levels;
  std::vector<Vec> sphere;
  std::vector<Face> F;
  icosphere(levels, sphere, F);
  Vertices V;
  for (const Vec& u : sphere) V.add(surface, u, -1);

  // Target edge length from the area: an equilateral triangle of side L has area sqrt(3)/4 L^2.
  const double area = surface_area(V.pos, F);
  const double length = std::sqrt(4.0 * area / (std::sqrt(3.0) * settings.target_triangles));
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    for (int pass = 0; pass < 6 && split_long_edges(surface, V, F, 4.0 / 3.0 * length) > 0; ++pass) {
    }
    collapse_short_edges(surface, V, F, 0.8 * length, 4.0 / 3.0 * length);
    flip_edges(V, F);
    relax(surface, settings.center, V, F, 0.8);
  }
  flip_edges(V, F);
  relax(surface, settings.center, V, F, 0.5);
  return compact(V.pos, F);
}

}  // namespace systole::mesh::procedural
