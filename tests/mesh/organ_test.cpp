#include "mesh/organ.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

using scene::Region;
using scene::Selector;
using scene::SelectorKind;

// A 2 x 1 x 1 grid of points in two parts, "low" (x < 1) and "high".
OrganMesh two_part_box() {
  OrganMesh m;
  for (int i = 0; i <= 2; ++i) {
    for (int j = 0; j <= 1; ++j) {
      for (int k = 0; k <= 1; ++k) {
        m.surface.positions.emplace_back(i, j, k);
        m.vertex_part.push_back(i < 1 ? 0 : 1);
      }
    }
  }
  m.part_names = {"low", "high"};
  return m;
}

Region region(const std::string& name, std::vector<Selector> select, int line = 7) {
  Region r;
  r.name = name;
  r.select = std::move(select);
  r.origin = {"scene.yaml", line, 5};
  return r;
}

Selector selector(SelectorKind kind) {
  Selector s;
  s.kind = kind;
  s.origin = {"scene.yaml", 9, 9};
  return s;
}

int count_of(const std::vector<int>& regions, int r) {
  return static_cast<int>(std::count(regions.begin(), regions.end(), r));
}

TEST(AssignRegions, EachSelectorKind) {
  const OrganMesh m = two_part_box();  // 12 vertices.
  Selector part = selector(SelectorKind::kPart);
  part.part = "high";
  Selector sphere = selector(SelectorKind::kSphere);
  sphere.center = Eigen::Vector3d(0, 0, 0);
  sphere.radius_m = 1.01;  // (0,0,0) and its three neighbours.
  Selector box = selector(SelectorKind::kBox);
  box.min = Eigen::Vector3d(-1, -1, 0.5);
  box.max = Eigen::Vector3d(3, 3, 2);  // z = 1: six vertices.
  Selector half = selector(SelectorKind::kHalfSpace);
  half.point = Eigen::Vector3d(0, 0.5, 0);
  half.normal = Eigen::Vector3d(0, 1, 0);  // y = 1: six vertices.

  EXPECT_EQ(count_of(assign_regions(m, {region("all", {selector(SelectorKind::kAll)})}), 0), 12);
  EXPECT_EQ(count_of(assign_regions(m, {region("p", {part})}), 0), 8);
  EXPECT_EQ(count_of(assign_regions(m, {region("s", {sphere})}), 0), 4);
  EXPECT_EQ(count_of(assign_regions(m, {region("b", {box})}), 0), 6);
  EXPECT_EQ(count_of(assign_regions(m, {region("h", {half})}), 0), 6);
  // A union of selectors.
  EXPECT_EQ(count_of(assign_regions(m, {region("u", {box, half})}), 0), 9);
  // No select: the part named like the region.
  EXPECT_EQ(count_of(assign_regions(m, {region("low", {})}), 0), 4);
}

TEST(AssignRegions, LaterRegionsOverride) {
  const OrganMesh m = two_part_box();
  Selector high = selector(SelectorKind::kPart);
  high.part = "high";
  const std::vector<int> r = assign_regions(m, {region("body", {selector(SelectorKind::kAll)}), region("high", {high})});
  EXPECT_EQ(count_of(r, 0), 4);
  EXPECT_EQ(count_of(r, 1), 8);
  EXPECT_EQ(count_of(r, -1), 0);
  // Without regions every vertex is undriven.
  EXPECT_EQ(count_of(assign_regions(m, {}), -1), 12);
}

TEST(AssignRegions, ARegionALaterOneEmptiesIsAnErrorThatNamesBoth) {
  const OrganMesh m = two_part_box();
  Selector high = selector(SelectorKind::kPart);
  high.part = "high";
  try {
    assign_regions(m, {region("valve", {high}, 9), region("body", {selector(SelectorKind::kAll)}, 12)});
    FAIL() << "a region left with no vertex was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    const std::string what = e.what();
    EXPECT_NE(what.find("scene.yaml:9:5: region 'valve' keeps no vertex"), std::string::npos) << what;
    EXPECT_NE(what.find("later region ('body')"), std::string::npos) << what;
    EXPECT_NE(what.find("list 'valve' after it"), std::string::npos) << what;
  }
}

TEST(AssignRegions, EmptyRegionIsAnErrorWithItsOrigin) {
  const OrganMesh m = two_part_box();
  Selector far = selector(SelectorKind::kSphere);
  far.center = Eigen::Vector3d(10, 10, 10);
  far.radius_m = 0.5;
  try {
    assign_regions(m, {region("nowhere", {far}, 42)});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    const std::string what = e.what();
    EXPECT_NE(what.find("nowhere"), std::string::npos) << what;
    EXPECT_NE(what.find("scene.yaml:42"), std::string::npos) << what;
  }
}

/// The message assign_regions throws for `regions` on `m` (kDataError), or "".
std::string refusal(const OrganMesh& m, const std::vector<Region>& regions) {
  try {
    assign_regions(m, regions);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    return e.what();
  }
  return "";
}

Selector part_named(const std::string& name) {
  Selector s = selector(SelectorKind::kPart);
  s.part = name;
  return s;
}

TEST(AssignRegions, UnknownPartListsTheParts) {
  const OrganMesh m = two_part_box();
  for (const Region& r : {region("r", {part_named("middle")}), region("middle", {})}) {
    const std::string what = refusal(m, {r});
    EXPECT_NE(what.find("the mesh has no part 'middle'; its parts, nearest first: high, low"), std::string::npos) << what;
    EXPECT_NE(what.find("scene.yaml:"), std::string::npos) << what;
  }
  EXPECT_NE(refusal(m, {region("r", {part_named("middle")})}).find("region 'r': select.part: "), std::string::npos)
      << "names the key";
  EXPECT_NE(refusal(m, {region("middle", {})}).find("region 'middle' (no select: the part named like the region)"),
            std::string::npos);
}

// An atlas has thousands of parts: the message lists the nearest few, by the whole name or
// its last segment, not all of them.
TEST(AssignRegions, UnknownPartAmongManyListsTheNearestFew) {
  OrganMesh m = two_part_box();
  m.part_names = {"heart/left_atrium", "heart/right_atrium"};
  for (int i = 0; i < 30; ++i) m.part_names.push_back("vessel_" + std::to_string(i));
  const std::string what = refusal(m, {region("r", {part_named("left_atrum")})});
  EXPECT_NE(what.find("nearest of its 32 parts: heart/left_atrium, heart/right_atrium, "), std::string::npos) << what;
  EXPECT_EQ(what.find("vessel_29"), std::string::npos) << "lists 8, not 32: " << what;
}

// Nested names (an exported organ's "heart/left_atrium") are selected as listed, or by their
// last whole segments when only one part ends so; an exact name wins over an ending.
TEST(AssignRegions, NestedPartNamesAreSelectedWholeOrByTheirLastSegments) {
  OrganMesh m = two_part_box();  // Part 0: the 4 vertices at x = 0; part 1: the other 8.
  m.part_names = {"heart/chamber/low", "heart/high"};
  for (const std::string name : {"heart/chamber/low", "chamber/low", "low"}) {
    EXPECT_EQ(count_of(assign_regions(m, {region("r", {part_named(name)})}), 0), 4) << name;
  }
  EXPECT_EQ(count_of(assign_regions(m, {region("high", {})}), 0), 8) << "a region's own name, by its ending";
  EXPECT_NE(refusal(m, {region("r", {part_named("amber/low")})}).find("the mesh has no part 'amber/low'"),
            std::string::npos)
      << "whole segments only";
  m.part_names.push_back("high");  // Part 2: one vertex.
  m.also_in = {{0, 2}};
  EXPECT_EQ(count_of(assign_regions(m, {region("r", {part_named("high")})}), 0), 1) << "the exact name wins";
}

TEST(AssignRegions, AnEndingSharedByTwoPartsIsAnErrorNamingBoth) {
  OrganMesh m = two_part_box();
  m.part_names = {"heart/wall", "lungs/wall"};
  const std::string what = refusal(m, {region("wall", {})});
  EXPECT_NE(what.find("scene.yaml:7:5: region 'wall'"), std::string::npos) << what;
  EXPECT_NE(what.find("'wall' ends the names of 2 parts (heart/wall, lungs/wall): write the whole name"),
            std::string::npos)
      << what;
  EXPECT_EQ(count_of(assign_regions(m, {region("r", {part_named("lungs/wall")})}), 0), 8);
}

TEST(BuildOrganGeometry, ProceduralHeartWithTransformAndRegions) {
  scene::Organ organ;
  organ.name = "heart";
  organ.mesh.procedural = "heart";
  organ.mesh.detail = 1;
  organ.transform.translate_m = Eigen::Vector3d(1, 2, 3);
  organ.transform.scale = 2;
  organ.regions = {region("left_ventricle", {}), region("apex", {})};
  const OrganGeometry g = build_organ_geometry(organ);
  EXPECT_TRUE(g.report.clean());
  EXPECT_GT(g.report.volume_m3, 0);
  // Centred, scaled, then moved: the bounding-box centre is the translation.
  Eigen::Vector3d lo = g.mesh.surface.positions.front(), hi = lo;
  for (const auto& p : g.mesh.surface.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_TRUE((0.5 * (lo + hi)).isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  EXPECT_GT(hi.y() - lo.y(), 0.2);  // Twice the ~12-15 cm heart.
  ASSERT_EQ(g.vertex_region.size(), g.mesh.surface.positions.size());
  EXPECT_GT(count_of(g.vertex_region, 0), 0);
  EXPECT_GT(count_of(g.vertex_region, 1), 0);
  EXPECT_GT(count_of(g.vertex_region, -1), 0);
}

TEST(BuildOrganGeometry, FileUnitsRotationAndInsideOutRepair) {
  // An inside-out cube in millimetres.
  TriangleMesh cube = testing::cube();
  std::string obj;
  for (const auto& p : cube.positions) obj += "v " + std::to_string(p.x() * 10) + " " + std::to_string(p.y() * 10) + " " + std::to_string(p.z() * 10) + "\n";
  for (const auto& t : cube.triangles) obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[2] + 1) + " " + std::to_string(t[1] + 1) + "\n";
  const auto file = testing::scratch("inside_out_cube.obj");
  testing::write_text(file, obj);

  scene::Organ organ;
  organ.name = "box";
  organ.mesh.file = file.string();
  organ.mesh.unit_m = 0.001;
  organ.transform.rotate_rad = Eigen::Vector3d(0, 0, M_PI / 2);  // +X goes to +Y.
  organ.transform.translate_m = Eigen::Vector3d(0.5, 0, 0);
  Selector right = selector(SelectorKind::kHalfSpace);
  right.point = Eigen::Vector3d(0.5, 0, 0);
  right.normal = Eigen::Vector3d(0, 1, 0);  // Selectors act in world space.
  organ.regions = {region("top", {right})};
  const OrganGeometry g = build_organ_geometry(organ);
  EXPECT_TRUE(g.report.clean());
  EXPECT_NEAR(g.report.volume_m3, 1e-6, 1e-12);  // Flipped to face outwards.
  bool noted = false;
  for (const auto& n : g.report.notes) noted |= n.find("inside out") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_EQ(count_of(g.vertex_region, 0), 4);
  for (const auto& p : g.mesh.surface.positions) EXPECT_NEAR(std::abs(p.x() - 0.5), 0.005, 1e-12);
}

TEST(BuildOrganGeometry, TrianglesDroppedOnImportAreReported) {
  // A closed cube plus two faces with a repeated corner: one as written, one after welding
  // two corners that lie 1e-9 apart.
  TriangleMesh cube = testing::cube();
  std::string obj;
  for (const auto& p : cube.positions) obj += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  obj += "v 0.000000001 0 0\n";
  for (const auto& t : cube.triangles) obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  obj += "f 1 1 2\n";
  obj += "f 1 9 3\n";
  const auto file = testing::scratch("cube_with_slivers.obj");
  testing::write_text(file, obj);
  scene::Organ organ;
  organ.name = "box";
  organ.mesh.file = file.string();
  organ.mesh.unit_m = 1;
  const OrganGeometry g = build_organ_geometry(organ);
  EXPECT_EQ(g.mesh.dropped_triangles, 2);
  EXPECT_EQ(g.mesh.surface.triangles.size(), 12u);
  bool noted = false;
  for (const auto& n : g.report.notes) noted |= n.starts_with("dropped triangles: 2 of the file's had a repeated corner");
  EXPECT_TRUE(noted) << "validate's mesh report says what was left out";
}

TEST(BuildOrganGeometry, NoMeshIsAnError) {
  scene::Organ organ;
  organ.name = "ghost";
  EXPECT_THROW(build_organ_geometry(organ), Error);
}

}  // namespace
}  // namespace systole::mesh
