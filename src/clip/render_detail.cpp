#include "clip/render_detail.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "clip/camera_framing.h"
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

/// Simplifies a big mesh within a pixel, the smallest the clip makes of it.
void simplify(const scene::Scene& scene, const world::World& world, std::size_t organ, RenderDetail& detail) {
  const mesh::TriangleMesh& surface = world.organs[organ].geometry.mesh.surface;
  const render::BoundingSphere sphere = bounding_sphere(world, {organ});
  detail.pixel_m = smallest_pixel_m(scene, scene.organs[organ].name, sphere.center, sphere.radius);
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
  const std::vector<char>& closed = world.organs[organ].geometry.report.in_closed_piece;
  const auto open_from = std::stable_partition(detail.triangles.begin(), detail.triangles.end(),
                                               [&](const Eigen::Vector3i& t) {
                                                 return static_cast<std::size_t>(t[0]) < closed.size() && closed[t[0]];
                                               });
  detail.two_sided_from = static_cast<int>(open_from - detail.triangles.begin());
  if (const std::vector<int>& inside = world.organs[organ].geometry.mesh.anatomy.enclosed_vertices; !inside.empty()) {
    std::vector<char> is_inside(surface.positions.size(), 0);
    for (int v : inside) is_inside[static_cast<std::size_t>(v)] = 1;
    for (const Eigen::Vector3i& t : detail.triangles) detail.enclosed.push_back(is_inside[t[0]] && is_inside[t[1]] && is_inside[t[2]]);
  }
  return detail;
}

}  // namespace systole::clip
