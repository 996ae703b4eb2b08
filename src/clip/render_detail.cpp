#include "clip/render_detail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "clip/camera_motion.h"
#include "mesh/simplify.h"

namespace systole::clip {
namespace {

/// The side of the smallest pixel any view of the clip makes on the organ's bounding
/// sphere (centre, radius) at any frame; 0 when a camera comes inside it. unit: m
double smallest_pixel_m(const scene::Scene& scene, const std::string& organ, const Eigen::Vector3d& centre,
                        double radius) {
  const auto& out = scene.output;
  const int views = std::max<int>(1, static_cast<int>(scene.views.size()));
  const auto rects = scene.views.empty() ? std::vector<scene::PixelRect>{{0, 0, out.width, out.height}}
                                         : scene::view_rectangles(out.width, out.height, views);
  double smallest = std::numeric_limits<double>::infinity();
  for (int v = 0; v < views; ++v) {
    const scene::View* view = scene.views.empty() ? nullptr : &scene.views[static_cast<std::size_t>(v)];
    if (view && !view->organs.empty() && std::find(view->organs.begin(), view->organs.end(), organ) == view->organs.end()) {
      continue;
    }
    const scene::Camera& camera = view && view->has_camera ? view->camera : scene.camera;
    const bool moves = camera.orbit.enabled || !camera.path.empty();
    const int frames = moves ? out.frame_count() : 1;
    for (int f = 0; f < frames; ++f) {
      const scene::Camera at = camera_at(camera, f / out.fps);
      const double nearest_m = (at.position_m - centre).norm() - radius;
      if (nearest_m <= 0) return 0;
      const double height_px = std::max(1, rects[static_cast<std::size_t>(v)].height);
      smallest = std::min(smallest, 2 * nearest_m * std::tan(at.fov_rad / 2) / height_px);
    }
  }
  return std::isfinite(smallest) ? smallest : 0;
}

/// Per vertex: whether its connected piece of `surface` is closed (every edge shared by
/// exactly two triangles that run it in opposite directions) and faces outwards (positive
/// volume).
std::vector<char> in_closed_piece(const mesh::TriangleMesh& surface) {
  const int n = static_cast<int>(surface.positions.size());
  std::vector<int> parent(n);
  for (int v = 0; v < n; ++v) parent[v] = v;
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  struct Edge {
    int lo, hi;
    bool forward;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * surface.triangles.size());
  for (const auto& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), a < b});
      parent[root(a)] = root(b);
    }
  }
  std::vector<char> closed(n, 1);
  std::vector<double> volume(n, 0);
  for (const auto& t : surface.triangles) {
    const auto& p = surface.positions;
    volume[root(t[0])] += p[t[0]].dot(p[t[1]].cross(p[t[2]])) / 6;
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& a, const Edge& b) { return std::tie(a.lo, a.hi, a.forward) < std::tie(b.lo, b.hi, b.forward); });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    // Exactly one use each way round: [backward, forward] after the sort.
    if (j - i != 2 || edges[i].forward || !edges[i + 1].forward) closed[root(edges[i].lo)] = 0;
    i = j;
  }
  std::vector<char> out(n);
  for (int v = 0; v < n; ++v) out[v] = closed[root(v)] && volume[root(v)] > 0;
  return out;
}


/// Simplifies a big mesh within a pixel, the smallest the clip makes of it.
void simplify(const scene::Scene& scene, const world::World& world, std::size_t organ, RenderDetail& detail) {
  const mesh::TriangleMesh& surface = world.organs[organ].geometry.mesh.surface;
  Eigen::Vector3d lo = surface.positions.front(), hi = lo;
  for (const auto& p : surface.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double radius = 0.5 * (hi - lo).norm();
  detail.pixel_m = smallest_pixel_m(scene, scene.organs[organ].name, centre, radius);
  if (detail.pixel_m <= 0) return;
  mesh::SimplifiedTriangles simplified = mesh::simplify(surface, kSimplifyError_px * detail.pixel_m);
  detail.triangles = std::move(simplified.triangles);
  detail.error_m = simplified.error_m;
}

}  // namespace

RenderDetail render_detail(const scene::Scene& scene, const world::World& world, std::size_t organ) {
  const mesh::TriangleMesh& surface = world.organs[organ].geometry.mesh.surface;
  RenderDetail detail;
  detail.full_triangles = surface.triangles.size();
  detail.triangles = surface.triangles;
  if (surface.triangles.size() > kSimplifyFromTriangles && !surface.positions.empty()) simplify(scene, world, organ, detail);
  const std::vector<char> closed = in_closed_piece(surface);
  const auto open_from = std::stable_partition(detail.triangles.begin(), detail.triangles.end(),
                                               [&](const Eigen::Vector3i& t) { return closed[t[0]] != 0; });
  detail.two_sided_from = static_cast<int>(open_from - detail.triangles.begin());
  return detail;
}

}  // namespace systole::clip
