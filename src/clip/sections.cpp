#include "clip/sections.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "clip/camera_framing.h"
#include "common/error.h"

namespace systole::clip {
namespace {

/// The heart's landmarks for cutting: the long axis and the line between the ventricles.
struct HeartFrame {
  Eigen::Vector3d annulus, apex, axis, side;  ///< axis: base to apex; side: left ventricle to right.
};

Eigen::Vector3d lining_centroid(const mesh::Cavity& cavity, const std::vector<Eigen::Vector3d>& x) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& t : cavity.lining) sum += x[t[0]] + x[t[1]] + x[t[2]];
  return sum / (3.0 * static_cast<double>(cavity.lining.size()));
}

HeartFrame heart_frame(const mesh::OrganMesh& mesh) {
  const auto& x = mesh.surface.positions;
  const mesh::Anatomy& a = mesh.anatomy;
  HeartFrame f;
  f.annulus = Eigen::Vector3d::Zero();
  for (int v : a.left_ventricle.annulus) f.annulus += x[v];
  f.annulus /= static_cast<double>(a.left_ventricle.annulus.size());
  f.apex = x[a.left_ventricle.apex];
  f.axis = (f.apex - f.annulus).normalized();
  Eigen::Vector3d left = Eigen::Vector3d::Zero(), right = Eigen::Vector3d::Zero();
  if (const mesh::Cavity* c = a.cavity("left_ventricle")) left = lining_centroid(*c, x);
  if (const mesh::Cavity* c = a.cavity("right_ventricle")) right = lining_centroid(*c, x);
  f.side = right - left;
  f.side = (f.side - f.side.dot(f.axis) * f.axis).normalized();
  return f;
}

/// Point, normal (to the side kept) and the camera's up for a section.
void section_plane(scene::Section section, const HeartFrame& f, scene::ClipPlane& clip, Eigen::Vector3d& up) {
  if (section == scene::Section::kFourChamber) {
    clip.point_m = f.annulus;
    clip.normal = f.axis.cross(f.side).normalized();
    if (clip.normal.z() > 0) clip.normal = -clip.normal;  // Keep the back half; look from the front.
    up = -f.axis;                                         // Atria above, apex below.
  } else {
    clip.point_m = f.annulus + 0.45 * (f.apex - f.annulus);  // Mid-ventricle, the papillary muscles' level.
    clip.normal = -f.axis;                                    // Keep the basal half; look from the apex.
    up = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(f.axis) * f.axis;  // The front wall up.
  }
}

const char* section_name(scene::Section s) { return s == scene::Section::kFourChamber ? "four_chamber" : "short_axis"; }

/// The first organ among `names` (every organ when empty) with an anatomy, or -1.
int anatomical_organ(const scene::Scene& scene, const world::World& world, const std::vector<std::string>& names) {
  for (std::size_t o = 0; o < scene.organs.size(); ++o) {
    const bool shown = names.empty() || std::find(names.begin(), names.end(), scene.organs[o].name) != names.end();
    if (shown && !world.organs[o].geometry.mesh.anatomy.empty()) return static_cast<int>(o);
  }
  return -1;
}

[[noreturn]] void no_heart(const scene::Origin& origin, const std::string& what, scene::Section section) {
  std::string where = origin.file.empty() ? "" : origin.file + ":" + std::to_string(origin.line) + ": ";
  throw Error(ExitCode::kDataError, where + what + ": section " + section_name(section) +
                                        " cuts a generated anatomical heart (mesh: {procedural: anatomical_heart}); "
                                        "none is shown here: give point and normal instead");
}

}  // namespace

void place_sections(scene::Scene& scene, const world::World& world, const std::vector<double>& aspect) {
  for (std::size_t o = 0; o < scene.organs.size(); ++o) {
    scene::ClipPlane& clip = scene.organs[o].clip;
    if (!clip.enabled || clip.section == scene::Section::kNone) continue;
    if (world.organs[o].geometry.mesh.anatomy.empty()) no_heart(scene.organs[o].origin, "organ '" + scene.organs[o].name + "'", clip.section);
    Eigen::Vector3d up;
    section_plane(clip.section, heart_frame(world.organs[o].geometry.mesh), clip, up);
  }
  for (std::size_t v = 0; v < scene.views.size(); ++v) {
    scene::View& view = scene.views[v];
    if (!view.clip.enabled || view.clip.section == scene::Section::kNone) continue;
    const int o = anatomical_organ(scene, world, view.organs);
    if (o < 0) no_heart(view.origin, "views[" + std::to_string(v) + "].clip", view.clip.section);
    Eigen::Vector3d up;
    section_plane(view.clip.section, heart_frame(world.organs[o].geometry.mesh), view.clip, up);
    // No camera position of its own: square at the cut, from the side cut away.
    const bool own_position = view.has_camera && !view.camera.automatic;
    if (own_position) continue;
    scene::Camera camera = view.has_camera ? view.camera : scene.camera;
    const render::BoundingSphere sphere = bounding_sphere(world, {static_cast<std::size_t>(o)});
    const Eigen::Vector3d& n = view.clip.normal;
    camera.target_m = sphere.center - (sphere.center - view.clip.point_m).dot(n) * n;  // In the cut.
    camera.position_m = camera.target_m - n * framing_distance(camera, sphere, aspect[v]);
    camera.up = up.normalized();
    camera.automatic = false;
    camera.orbit.enabled = false;
    camera.path.clear();
    view.camera = camera;
    view.has_camera = true;
  }
}

}  // namespace systole::clip
