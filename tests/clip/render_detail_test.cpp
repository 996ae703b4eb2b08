// ctest-labels: slow-under-sanitizers
// What a clip draws of an organ's mesh: a big mesh simplified within the smallest pixel its
// cameras make of it (and whole when a camera comes inside it); the triangles of
// closed pieces first (culled), then the open pieces' (two-sided).

#include "clip/render_detail.h"

#include <gtest/gtest.h>

#include "clip/camera_framing.h"
#include "mesh/gltf_writer.h"
#include "mesh/icosphere.h"
#include "scene/load.h"
#include "support/run.h"
#include "support/shapes.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using mesh::testing::GltfPart;
using mesh::testing::write_parts_gltf;

/// The one organ of a scene on `file` with `extra` scene lines, and what is drawn of it.
struct Drawn {
  std::vector<Eigen::Vector3d> positions;  ///< The organ's rest vertices (world space).
  clip::RenderDetail detail;
};

Drawn drawn(const fs::path& file, const std::string& extra) {
  const std::string yaml = "organs:\n  - name: organ\n    mesh: {file: " + file.string() + "}\n" + extra;
  const scene::Scene s = scene::load_from_string(yaml, (file.parent_path() / "scene.yaml").string(), {});
  const world::World w = world::build_world(s);
  return {w.organs[0].geometry.mesh.surface.positions, clip::render_detail(clip::with_cameras_placed(s, w), w, 0)};
}

TEST(RenderDetail, ClosedPiecesComeFirstAndOpenOnesAreTwoSided) {
  const fs::path dir = scratch("render_detail_pieces");
  const mesh::TriangleMesh ball = mesh::icosphere(0.02, 2);  // 320 triangles, closed.
  write_parts_gltf(dir / "parts.gltf", {}, {GltfPart{"sheet", "sheet", "m", {sheet(4, 0.06, Eigen::Vector3d(-0.03, -0.03, -0.03))}},
                                           GltfPart{"ball", "ball", "m", {ball}}});
  const auto [positions, d] = drawn(dir / "parts.gltf", "output: {width: 320, height: 240}\n");
  EXPECT_EQ(d.full_triangles, 320u + 32u);
  ASSERT_EQ(d.triangles.size(), d.full_triangles) << "a small mesh is drawn whole";
  EXPECT_EQ(d.pixel_m, 0);
  ASSERT_EQ(d.two_sided_from, 320);
  // The ball's triangles first, the sheet's (all corners at the lowest z) after.
  double lowest = 1;
  for (const auto& p : positions) lowest = std::min(lowest, p.z());
  for (std::size_t t = 0; t < d.triangles.size(); ++t) {
    bool on_sheet = true;
    for (int k = 0; k < 3; ++k) on_sheet = on_sheet && std::abs(positions[d.triangles[t][k]].z() - lowest) < 1e-9;
    EXPECT_EQ(on_sheet, static_cast<int>(t) >= d.two_sided_from) << "triangle " << t;
  }
}

TEST(RenderDetail, ABigMeshIsDrawnWithinAPixelOfItsSmallestPixel) {
  const fs::path dir = scratch("render_detail_big");
  const double radius = 0.05;
  write_parts_gltf(dir / "ball.gltf", {}, {GltfPart{"ball", "ball", "m", {mesh::icosphere(radius, 6)}}});  // 81920
  const clip::RenderDetail small = drawn(dir / "ball.gltf", "output: {width: 320, height: 240}\n").detail;
  const clip::RenderDetail large = drawn(dir / "ball.gltf", "output: {width: 1280, height: 720}\n").detail;
  EXPECT_EQ(small.full_triangles, 81920u);
  EXPECT_LT(small.triangles.size(), small.full_triangles / 4);
  EXPECT_LT(small.triangles.size(), large.triangles.size()) << "a finer frame keeps more";
  for (const clip::RenderDetail* d : {&small, &large}) {
    EXPECT_GT(d->pixel_m, 0);
    EXPECT_LE(d->error_m, clip::kSimplifyError_px * d->pixel_m);
    EXPECT_EQ(d->two_sided_from, static_cast<int>(d->triangles.size())) << "a closed ball: all culled";
  }
  // The same camera (the frame's vertical angle is the smaller in both): a pixel 720 / 240
  // times as large on the organ.
  EXPECT_NEAR(small.pixel_m / large.pixel_m, 3.0, 1e-9);
}

TEST(RenderDetail, ACameraInsideTheOrganDrawsItWhole) {
  const fs::path dir = scratch("render_detail_inside");
  write_parts_gltf(dir / "ball.gltf", {}, {GltfPart{"ball", "ball", "m", {mesh::icosphere(0.05, 6)}}});
  const std::string camera = "camera: {position: [0, 0, 0.01], target: [0, 0, 0]}\noutput: {width: 320, height: 240}\n";
  const clip::RenderDetail d = drawn(dir / "ball.gltf", camera).detail;
  EXPECT_EQ(d.triangles.size(), d.full_triangles);
  EXPECT_EQ(d.pixel_m, 0);
}

}  // namespace
}  // namespace systole::test
