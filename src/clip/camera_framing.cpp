#include "clip/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "clip/camera_motion.h"
#include "clip/sections.h"
#include "common/error.h"
#include "render/camera_matrices.h"

namespace systole::clip {
namespace {

/// Indices of the organs a view shows (every organ when it names none).
std::vector<std::size_t> shown_organs(const scene::Scene& scene, const std::vector<std::string>& names) {
  std::vector<std::size_t> shown;
  for (std::size_t o = 0; o < scene.organs.size(); ++o) {
    if (names.empty() || std::find(names.begin(), names.end(), scene.organs[o].name) != names.end()) shown.push_back(o);
  }
  return shown;
}


void place(scene::Camera& camera, const render::BoundingSphere& sphere, double aspect) {
  if (!camera.automatic) return;
  camera.target_m = sphere.center;
  camera.position_m = sphere.center + Eigen::Vector3d(0, 0, framing_distance(camera, sphere, aspect));
}

std::string point_text(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g) m", p.x(), p.y(), p.z());
  return text;
}

/// Why `body` covers no pixel of a view, or "" when it does.
std::string why_not_seen(const world::OrganBody& body, const Eigen::Vector3d& centre, const scene::Camera& camera,
                         const scene::PixelRect& rect) {
  const auto& positions = body.geometry.mesh.surface.positions;
  const Eigen::Matrix4d view = render::look_at(camera);
  render::DepthRange depth;
  depth.near_m = 1e-9;
  depth.far_m = 1e12;
  const Eigen::Matrix4d projection = render::perspective(camera.fov_rad, double(rect.width) / rect.height, depth);
  int in_front = 0, in_view = 0;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (const Eigen::Vector3d& p : positions) {
    const Eigen::Vector4d eye = view * p.homogeneous();
    if (eye.z() >= 0) continue;  // Behind the eye (it looks down -z).
    ++in_front;
    const Eigen::Vector4d clip = projection * eye;
    const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
    lo = lo.cwiseMin(ndc), hi = hi.cwiseMax(ndc);
    if (std::abs(ndc.x()) <= 1 && std::abs(ndc.y()) <= 1) ++in_view;
  }
  const std::string where = "the organ is around " + point_text(centre) + ", the camera at " +
                            point_text(camera.position_m) + " looks at " + point_text(camera.target_m);
  if (in_front == 0) return "it is behind the camera (" + where + ")";
  // The projected extent, in pixels: an organ can lie across the view with no vertex in it.
  const Eigen::Vector2d pixels = 0.5 * (hi - lo).cwiseProduct(Eigen::Vector2d(rect.width, rect.height));
  const bool overlaps = hi.x() >= -1 && lo.x() <= 1 && hi.y() >= -1 && lo.y() <= 1;
  if (in_view == 0 && !overlaps) return "it is outside the view (" + where + ")";
  if (pixels.maxCoeff() < 1) {
    char size[64];
    std::snprintf(size, sizeof size, "%.2g", pixels.maxCoeff());
    return std::string("it is too small to cover a pixel (") + size + " px across): the camera is too far, or the mesh's "
           "units make it too small";
  }
  return "";
}

}  // namespace

double framing_distance(const scene::Camera& camera, const render::BoundingSphere& sphere, double aspect) {
  // The smaller of the vertical and horizontal angles of view decides what fits.
  const double vertical = camera.fov_rad;
  const double horizontal = 2 * std::atan(std::tan(vertical / 2) * aspect);
  const double half_angle = 0.5 * camera.fill * std::min(vertical, horizontal);
  return std::max(sphere.radius, 1e-6) / std::sin(half_angle);
}

render::BoundingSphere bounding_sphere(const world::World& world, const std::vector<std::size_t>& organs) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const std::size_t o : organs) {
    for (const Eigen::Vector3d& p : world.organs[o].geometry.mesh.surface.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  render::BoundingSphere sphere;
  if (lo.x() > hi.x()) return sphere;
  sphere.center = 0.5 * (lo + hi);
  for (const std::size_t o : organs) {
    for (const Eigen::Vector3d& p : world.organs[o].geometry.mesh.surface.positions) {
      sphere.radius = std::max(sphere.radius, (p - sphere.center).norm());
    }
  }
  return sphere;
}

scene::Scene with_cameras_placed(scene::Scene scene, const world::World& world) {
  const double aspect = double(scene.output.width) / scene.output.height;
  place(scene.camera, bounding_sphere(world, shown_organs(scene, {})), aspect);
  const auto rects = scene::view_rectangles(scene.output.width, scene.output.height, static_cast<int>(scene.views.size()));
  std::vector<double> aspects;
  for (const auto& r : rects) aspects.push_back(double(r.width) / r.height);
  place_sections(scene, world, aspects);
  for (std::size_t v = 0; v < scene.views.size(); ++v) {
    scene::View& view = scene.views[v];
    if (view.has_camera) {
      place(view.camera, bounding_sphere(world, shown_organs(scene, view.organs)),
            double(rects[v].width) / rects[v].height);
    }
  }
  return scene;
}

void check_organs_in_view(const scene::Scene& scene, const world::World& world) {
  std::vector<std::string> causes;
  const auto check = [&](const scene::Camera& camera, const scene::PixelRect& rect, const std::vector<std::string>& names) {
    const scene::Camera first = camera_at(camera, 0);
    for (const std::size_t o : shown_organs(scene, names)) {
      const std::string cause = why_not_seen(world.organs[o], bounding_sphere(world, {o}).center, first, rect);
      if (cause.empty()) return true;
      causes.push_back("organ '" + scene.organs[o].name + "': " + cause);
    }
    return false;
  };
  if (scene.views.empty()) {
    if (check(scene.camera, {0, 0, scene.output.width, scene.output.height}, {})) return;
  } else {
    const auto rects = scene::view_rectangles(scene.output.width, scene.output.height, static_cast<int>(scene.views.size()));
    for (std::size_t v = 0; v < scene.views.size(); ++v) {
      const scene::View& view = scene.views[v];
      if (check(view.has_camera ? view.camera : scene.camera, rects[v], view.organs)) return;
    }
  }
  std::string message = scene.path + ": no organ would be seen in the first frame, so the video would show only the "
                                     "background: ";
  for (std::size_t i = 0; i < causes.size(); ++i) message += (i ? "; " : "") + causes[i];
  message += ". Remove camera.position and camera.target to let the camera frame the organs, or check mesh.units";
  throw Error(ExitCode::kDataError, message);
}

}  // namespace systole::clip
