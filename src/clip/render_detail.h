#pragma once
// How many of an organ's triangles the clip draws. A mesh of more than
// kSimplifyFromTriangles triangles (an atlas organ) is drawn simplified within a pixel of
// its full surface, the pixel being the smallest the clip's cameras make of it: at the
// nearest approach of each camera over the clip, in every view that shows it
// (mesh/simplify.h: meshoptimizer's error is held to kSimplifyError_px, and the surface
// between its vertices strays up to twice as far). Smaller meshes, every generated organ
// included, are drawn whole.
//
// The triangles of pieces that are closed and face outwards come first: their back faces
// are always hidden by their front faces and are culled; the rest (open parts, an atlas
// organ's sheets) are drawn two-sided. A rasterizer spends on a back face what it spends
// on a front one. An anatomical heart's linings and inner valves, half its triangles, are
// marked enclosed: a view that neither cuts nor sees through the heart leaves them out.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "scene/scene.h"
#include "world/world.h"

namespace systole::clip {

inline constexpr std::size_t kSimplifyFromTriangles = 50000;
inline constexpr double kSimplifyError_px = 0.4;

struct RenderDetail {
  std::vector<Eigen::Vector3i> triangles;  ///< What to draw, over the surface's vertices.
  int two_sided_from = 0;  ///< triangles[two_sided_from ..] belong to open pieces (drawn two-sided).
  /// Per triangle: inside the organ's closed outside (mesh::Anatomy::enclosed_vertices, every
  /// corner), drawn only by views that cut it, see through it or come inside it
  /// (render::Renderer::set_enclosed). Empty: none.
  std::vector<char> enclosed;
  std::size_t full_triangles = 0;          ///< The surface's own triangle count.
  double pixel_m = 0;  ///< The smallest pixel on the organ over the clip; 0: not simplified. unit: m
  double error_m = 0;  ///< mesh::SimplifiedTriangles::error_m of the drawn triangles. unit: m
};

/// The triangles to draw for organ `organ` of `world`, with cameras placed
/// (with_cameras_placed). A camera inside the organ's bounding sphere sees it up close:
/// the mesh is then drawn whole.
RenderDetail render_detail(const scene::Scene& scene, const world::World& world, std::size_t organ);

}  // namespace systole::clip
