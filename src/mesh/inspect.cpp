#include "mesh/inspect.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace systole::mesh {
namespace {

// One directed edge of a triangle, keyed by its undirected vertex pair.
struct EdgeUse {
  int lo, hi;     // Vertex indices, lo < hi.
  bool forward;   // The triangle walks lo -> hi.
  int triangle;
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) {
    parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    i = parent[static_cast<size_t>(i)];
  }
  return i;
}

std::string edge_at(const TriangleMesh& mesh, int a, int b) {
  return "between " + format_position(mesh.positions[static_cast<size_t>(a)]) + " and " +
         format_position(mesh.positions[static_cast<size_t>(b)]);
}

// The first example of each finding, for the notes.
struct Examples {
  int invalid = -1, degenerate = -1, unused = -1;
  std::array<int, 2> boundary{-1, -1}, nonmanifold{-1, -1}, inconsistent{-1, -1};
};

// Triangles that can be measured at all: indices in range, finite corners.
std::vector<char> find_valid(const TriangleMesh& mesh, MeshReport& report, Examples& first) {
  const int n = static_cast<int>(mesh.positions.size());
  std::vector<char> valid(mesh.triangles.size(), 0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    bool ok = (tri.array() >= 0).all() && (tri.array() < n).all();
    for (int k = 0; ok && k < 3; ++k) ok = mesh.positions[static_cast<size_t>(tri[k])].allFinite();
    valid[t] = ok;
    if (!ok && first.invalid < 0) first.invalid = static_cast<int>(t);
    report.invalid_triangles += !ok;
  }
  return valid;
}

// Degenerate: a repeated index, or an area negligible against the longest edge
// (collinear corners), measured relative so it holds at any scale.
void count_degenerate(const TriangleMesh& mesh, const std::vector<char>& valid, MeshReport& report, Examples& first) {
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!valid[t]) continue;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    bool degenerate = tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
    if (!degenerate) {
      const Eigen::Vector3d& a = mesh.positions[static_cast<size_t>(tri[0])];
      const Eigen::Vector3d& b = mesh.positions[static_cast<size_t>(tri[1])];
      const Eigen::Vector3d& c = mesh.positions[static_cast<size_t>(tri[2])];
      const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
      degenerate = (b - a).cross(c - a).norm() <= 1e-12 * longest2;
    }
    if (degenerate) {
      ++report.degenerate_triangles;
      if (first.degenerate < 0) first.degenerate = static_cast<int>(t);
    }
  }
}

// Edges: sort every directed use by its vertex pair, then count uses per pair. Returns a
// vertex of every edge that is not closed and consistent.
std::vector<int> count_edges(const TriangleMesh& mesh, const std::vector<char>& valid, MeshReport& report,
                             Examples& first) {
  std::vector<EdgeUse> uses;
  uses.reserve(mesh.triangles.size() * 3);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!valid[t]) continue;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      if (a == b) continue;  // A repeated index has no edge there.
      uses.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<int>(t)});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.lo, x.hi, x.triangle, x.forward) < std::tie(y.lo, y.hi, y.triangle, y.forward);
  });
  std::vector<int> open_at;
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    const size_t count = j - i;
    if (count != 2 || uses[i].forward == uses[i + 1].forward) open_at.push_back(uses[i].lo);
    if (count == 1) {
      if (report.boundary_edges++ == 0) first.boundary = {uses[i].lo, uses[i].hi};
    } else if (count >= 3) {
      if (report.nonmanifold_edges++ == 0) first.nonmanifold = {uses[i].lo, uses[i].hi};
    } else if (uses[i].forward == uses[i + 1].forward) {
      if (report.inconsistent_edges++ == 0) first.inconsistent = {uses[i].lo, uses[i].hi};
    }
    i = j;
  }
  return open_at;
}

// Connected pieces of triangles (union-find over vertices): each vertex's parent, and
// which vertices a valid triangle uses.
struct Pieces {
  std::vector<int> parent;
  std::vector<char> used;
};

Pieces count_pieces(const TriangleMesh& mesh, const std::vector<char>& valid, MeshReport& report, Examples& first) {
  const int n = static_cast<int>(mesh.positions.size());
  Pieces pieces{std::vector<int>(static_cast<size_t>(n)), std::vector<char>(static_cast<size_t>(n), 0)};
  std::vector<int>& parent = pieces.parent;
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!valid[t]) continue;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) pieces.used[static_cast<size_t>(tri[k])] = 1;
    const int r0 = find_root(parent, tri[0]);
    for (int k = 1; k < 3; ++k) {
      const int r = find_root(parent, tri[k]);
      if (r != r0) parent[static_cast<size_t>(std::max(r, r0))] = std::min(r, r0);
    }
  }
  for (int v = 0; v < n; ++v) {
    if (!pieces.used[static_cast<size_t>(v)]) {
      if (report.unused_vertices++ == 0) first.unused = v;
    } else if (find_root(parent, v) == v) {
      ++report.components;
    }
  }
  return pieces;
}

// Signed volume by the divergence theorem, about the bounding-box centre so large
// coordinates do not cancel digits; and which vertices lie in a closed piece of positive
// volume.
void measure_volume(const TriangleMesh& mesh, const std::vector<char>& valid, Pieces& pieces,
                    const std::vector<int>& open_at, MeshReport& report) {
  const int n = static_cast<int>(mesh.positions.size());
  std::vector<int>& parent = pieces.parent;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Eigen::Vector3d& p : mesh.positions) {
    if (p.allFinite()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d centre = report.vertices > 0 && (hi.array() >= lo.array()).all()
                                     ? Eigen::Vector3d(0.5 * (lo + hi))
                                     : Eigen::Vector3d::Zero();
  double six_volume = 0;
  std::vector<double> piece_six_volume(static_cast<size_t>(n), 0.0);  // At each piece's root.
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!valid[t]) continue;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.positions[static_cast<size_t>(tri[0])] - centre;
    const Eigen::Vector3d b = mesh.positions[static_cast<size_t>(tri[1])] - centre;
    const Eigen::Vector3d c = mesh.positions[static_cast<size_t>(tri[2])] - centre;
    six_volume += a.dot(b.cross(c));
    piece_six_volume[static_cast<size_t>(find_root(parent, tri[0]))] += a.dot(b.cross(c));
  }
  report.volume_m3 = six_volume / 6.0;
  std::vector<char> piece_open(static_cast<size_t>(n), 0);
  for (const int v : open_at) piece_open[static_cast<size_t>(find_root(parent, v))] = 1;
  report.in_closed_piece.resize(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    const auto root = static_cast<size_t>(find_root(parent, v));
    report.in_closed_piece[static_cast<size_t>(v)] = pieces.used[static_cast<size_t>(v)] && !piece_open[root] && piece_six_volume[root] > 0;
  }
}

// Notes: what, where, and what Systole does about it.
void write_notes(const TriangleMesh& mesh, const Examples& first, MeshReport& report) {
  const int n = static_cast<int>(mesh.positions.size());
  const bool volume_usable = report.encloses_volume();
  const std::string no_volume = "; the volume constraint is disabled for this organ";
  auto count = [](int k, const char* what) { return std::to_string(k) + " " + what; };
  if (report.triangles == 0) report.notes.push_back("empty surface: no triangles; the organ cannot be simulated");
  if (report.invalid_triangles > 0) {
    const Eigen::Vector3i& t = mesh.triangles[static_cast<size_t>(first.invalid)];
    report.notes.push_back("invalid triangles: " + count(report.invalid_triangles, "with an index out of range or a non-finite corner") +
                           " (e.g. triangle " + std::to_string(first.invalid) + " = [" + std::to_string(t[0]) + ", " +
                           std::to_string(t[1]) + ", " + std::to_string(t[2]) + "] of " + std::to_string(n) +
                           " vertices); they are ignored by every check" + no_volume);
  }
  if (report.degenerate_triangles > 0) {
    const Eigen::Vector3i& t = mesh.triangles[static_cast<size_t>(first.degenerate)];
    report.notes.push_back("degenerate triangles: " + count(report.degenerate_triangles, "with zero area") + " (e.g. at " +
                           format_position(mesh.positions[static_cast<size_t>(t[0])]) +
                           "); they carry no area, so no mass, and give no normal");
  }
  if (report.boundary_edges > 0) {
    report.notes.push_back("open surface: " + count(report.boundary_edges, "boundary edges") + " (e.g. " +
                           edge_at(mesh, first.boundary[0], first.boundary[1]) + ")" + no_volume);
  }
  if (report.nonmanifold_edges > 0) {
    report.notes.push_back("non-manifold surface: " + count(report.nonmanifold_edges, "edges shared by three or more triangles") +
                           " (e.g. " + edge_at(mesh, first.nonmanifold[0], first.nonmanifold[1]) + ")" + no_volume);
  }
  if (report.inconsistent_edges > 0) {
    report.notes.push_back("inconsistent orientation: " + count(report.inconsistent_edges, "edges whose two triangles face opposite ways") +
                           " (e.g. " + edge_at(mesh, first.inconsistent[0], first.inconsistent[1]) +
                           "); shading is wrong there" + no_volume);
  }
  if (report.components > 1) {
    report.notes.push_back("separate pieces: " + std::to_string(report.components) +
                           " connected components; they move as one organ but share no springs");
  }
  if (report.unused_vertices > 0) {
    report.notes.push_back("unused vertices: " + count(report.unused_vertices, "vertices in no triangle") + " (e.g. at " +
                           format_position(mesh.positions[static_cast<size_t>(first.unused)]) +
                           "); they are not part of the surface and carry no springs");
  }
  if (volume_usable && report.volume_m3 < 0) {
    report.notes.push_back("inside out: the closed surface has negative volume (" + std::to_string(report.volume_m3) +
                           " m^3); its triangles face inwards");
  }
}

}  // namespace

std::string format_position(const Eigen::Vector3d& p) {
  char text[128];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g) m", p.x(), p.y(), p.z());
  return text;
}

MeshReport inspect(const TriangleMesh& mesh) {
  MeshReport report;
  report.vertices = static_cast<int>(mesh.positions.size());
  report.triangles = static_cast<int>(mesh.triangles.size());
  Examples first;
  const std::vector<char> valid = find_valid(mesh, report, first);
  count_degenerate(mesh, valid, report, first);
  const std::vector<int> open_at = count_edges(mesh, valid, report, first);
  Pieces pieces = count_pieces(mesh, valid, report, first);
  measure_volume(mesh, valid, pieces, open_at, report);
  write_notes(mesh, first, report);
  return report;
}

}  // namespace systole::mesh
