// Issue 37: a part that `systole validate` lists is selected by that name, as listed, end to
// end through the binary: Systole's own exports ("heart/left_atrium") and an atlas whose
// author used slashes, colons and YAML's special words in its names.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "mesh/gltf_writer.h"
#include "mesh/test_meshes.h"
#include "support/run.h"

namespace systole::test {
namespace {

/// A cube 5 cm on a side (8 vertices, 12 triangles) with its lowest corner at (x, 0, 0).
mesh::TriangleMesh cube_at(double x) {
  mesh::TriangleMesh c = mesh::testing::cube();
  for (auto& p : c.positions) p = 0.05 * p + Eigen::Vector3d(x, 0, 0);
  return c;
}

/// The part names a validate report lists, each as printed (quoted when YAML needs it).
std::vector<std::string> listed_parts(const std::string& report) {
  std::vector<std::string> names;
  std::istringstream lines(report);
  bool in_parts = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("  parts (select with `part: NAME`)")) {
      in_parts = true;
    } else if (in_parts && line.starts_with("    ") && line.ends_with("closed") != line.ends_with("open")) {
      names.push_back(line.substr(4, line.rfind(": ") - 4));  // "    NAME: 12 triangles, closed"
    } else {
      in_parts = false;
    }
  }
  return names;
}

/// Validates, for every name `mesh_file` lists, a scene whose one region selects it by the
/// name as printed; expects each to pass with a region of at least one vertex.
void expect_every_listed_part_selectable(const std::filesystem::path& dir, const std::string& mesh_file,
                                         std::size_t expected_parts) {
  test::write_file(dir / "list.yaml", "organs:\n  - name: heart\n    mesh: {file: " + mesh_file + "}\n");
  const RunResult listing = run(systole() + " validate " + (dir / "list.yaml").string());
  ASSERT_EQ(listing.exit_code, 0) << listing.output;
  const std::vector<std::string> names = listed_parts(listing.output);
  ASSERT_EQ(names.size(), expected_parts) << listing.output;
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    test::write_file(dir / "one.yaml", "organs:\n  - name: heart\n    mesh: {file: " + mesh_file +
                                           "}\n    regions:\n      - name: chosen\n        select: {part: " + name +
                                           "}\n");
    const RunResult r = run(systole() + " validate " + (dir / "one.yaml").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::size_t at = r.output.find("region chosen: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_GT(std::stoi(r.output.substr(at + 15)), 0) << r.output;
  }
}

// The exported heart lists its regions as "heart/<region>" materials: each is selected as
// listed, and the scene that made the file selects the same parts by its own region names.
TEST(PartNames, AnExportsPartsAreSelectedAsValidateListsThem) {
  const auto dir = scratch("part_names_export");
  test::write_file(dir / "small.yaml", R"(organs:
  - name: heart
    mesh: {procedural: heart, detail: 1}
    regions:
      - name: left_ventricle
        drive: {waveform: cardiac, rate: 120 bpm, amplitude: 0.1}
      - name: apex
        select: {sphere: {center: [0, -4 cm, 0], radius: 1.5 cm}}
output: {width: 64, height: 48, fps: 10, duration: 0.5 s}
)");
  const RunResult exported = run(systole() + " export " + (dir / "small.yaml").string() + " -o " + (dir / "small.glb").string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  // heart-0..2 (assimp's primitives), heart (mesh and node), heart/apex, heart/left_ventricle.
  expect_every_listed_part_selectable(dir, "small.glb", 6);

  // Back into the source scene: `left_ventricle` finds "heart/left_ventricle" by its last segment.
  const RunResult again = run(systole() + " validate " + (dir / "small.yaml").string() +
                              " -D 'organs.heart.mesh={file: small.glb}'");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("region left_ventricle: "), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("region left_ventricle: 0 vertices"), std::string::npos) << again.output;
}

// An atlas whose author named parts freely: slashes, a colon and space (quoted by validate),
// YAML's `null`, a `#`.
TEST(PartNames, AnAtlasesFreelyNamedPartsAreSelectedAsValidateListsThem) {
  const auto dir = scratch("part_names_atlas");
  mesh::testing::write_parts_gltf(dir / "atlas.gltf",
                                  {{"Chest: scan 1",
                                    {{"heart/left_atrium", "heart/left_atrium/mesh", "muscle #1", {cube_at(0)}},
                                     {"heart/right_atrium", "null", "muscle #1", {cube_at(0.1)}}}}},
                                  {{"valve", "valve.001", "Leaflet|soft", {cube_at(0.2)}}});
  // Nodes 4 (with the group), meshes 3, materials 2.
  expect_every_listed_part_selectable(dir, "atlas.gltf", 9);
  const RunResult listing = run(systole() + " validate " + (dir / "list.yaml").string());
  EXPECT_NE(listing.output.find("    \"Chest: scan 1\": 24 triangles"), std::string::npos)
      << "a name YAML would misread is listed quoted:\n" << listing.output;
  EXPECT_NE(listing.output.find("    heart/left_atrium: 12 triangles"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find("    \"null\": 12 triangles"), std::string::npos) << listing.output;

  // A region named by the last segment takes the one part ending so: 8 vertices, one cube.
  test::write_file(dir / "regions.yaml", R"(organs:
  - name: heart
    mesh: {file: atlas.gltf}
    regions:
      - name: left_atrium
      - name: ra
        select: {part: heart/right_atrium}
)");
  const RunResult regions = run(systole() + " validate " + (dir / "regions.yaml").string());
  ASSERT_EQ(regions.exit_code, 0) << regions.output;
  EXPECT_NE(regions.output.find("region left_atrium: 8 vertices"), std::string::npos) << regions.output;
  EXPECT_NE(regions.output.find("region ra: 8 vertices"), std::string::npos) << regions.output;
}

// A misspelt part names the file, the line, the region and the key, and lists the nearest
// names as validate would list them; an ending two parts share asks for the whole name.
TEST(PartNames, AnUnknownOrAmbiguousPartIsAnErrorWithTheNearestNames) {
  const auto dir = scratch("part_names_errors");
  mesh::testing::write_parts_gltf(dir / "atlas.gltf", {},
                                  {{"heart/wall", "a", "m", {cube_at(0)}}, {"lungs/wall", "b", "m", {cube_at(0.1)}}});
  test::write_file(dir / "typo.yaml", R"(organs:
  - name: heart
    mesh: {file: atlas.gltf}
    regions:
      - name: w
        select: {part: heart/wal}
)");
  RunResult r = run(systole() + " validate " + (dir / "typo.yaml").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("typo.yaml:6:24: region 'w': select.part: the mesh has no part 'heart/wal'; its parts, "
                          "nearest first: heart/wall, "),
            std::string::npos)
      << r.output;

  r = run(systole() + " validate " + (dir / "typo.yaml").string() + " -D organs.heart.regions.w.select.part=wall");
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("-D organs.heart.regions.w.select.part=wall: region 'w': select.part: 'wall' ends the names "
                          "of 2 parts (heart/wall, lungs/wall): write the whole name"),
            std::string::npos)
      << r.output;
  r = run(systole() + " validate " + (dir / "typo.yaml").string() + " -D organs.heart.regions.w.select.part=lungs/wall");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("region w: 8 vertices"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace systole::test
