// Mesh files are bounded before assimp reads them (mesh/file_bounds.h, mesh/assimp_read.h):
// a glTF's node graph by its count, depth and shape, any format's graph after parsing, OBJ
// and STL counts, and a file cut short. Small files, with the limits lowered where the real
// ones would need big files (tests/hostile/ runs those through the command line).

#include "mesh/file_bounds.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/warning.h"
#include "mesh/import.h"
#include "support/hostile_meshes.h"
#include "support/run.h"

namespace systole::mesh {
namespace {

namespace fs = std::filesystem;
using test::glb;
using test::write_binary;

/// The limits for one test, restored after it, and a folder of its own: ctest runs the
/// tests of one fixture in parallel processes, and a shared folder is wiped by the next one.
class FileBounds : public ::testing::Test {
 protected:
  void TearDown() override { import_limits() = ImportLimits{}; }
  fs::path dir_ =
      test::scratch(std::string("file_bounds/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
};

/// The message import_mesh refuses `file` with (kDataError), or "" if it reads it.
std::string refusal(const fs::path& file) {
  try {
    import_mesh(file);
    return "";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError) << e.what();
    return e.what();
  }
}

TEST_F(FileBounds, AGltfChainDeeperThanTheLimitIsRefusedByDepthAndReadWhenLifted) {
  const fs::path file = dir_ / "deep.glb";
  write_binary(file, glb(test::chain_nodes(300), "[0]"));
  EXPECT_NE(refusal(file).find("nests nodes over 256 levels deep"), std::string::npos) << refusal(file);
  write_binary(dir_ / "shallow.glb", glb(test::chain_nodes(200), "[0]"));
  EXPECT_EQ(refusal(dir_ / "shallow.glb"), "");
  import_limits() = ImportLimits::none();  // --allow-large: read, on the reader's own stack.
  EXPECT_EQ(import_mesh(file).surface.triangles.size(), 1u);
}

TEST_F(FileBounds, AGltfWithMoreNodesThanTheLimitIsRefusedBeforeReading) {
  import_limits().max_nodes = 50;
  std::string roots;
  const std::string nodes = test::wide_nodes(60, &roots);
  write_binary(dir_ / "wide.glb", glb(nodes, roots));
  EXPECT_NE(refusal(dir_ / "wide.glb").find("the glTF scene graph has over 50 nodes"), std::string::npos);
  import_limits().max_nodes = 60;
  EXPECT_EQ(refusal(dir_ / "wide.glb"), "");
}

TEST_F(FileBounds, TheVerticesAGltfsNodesPlaceAreCountedPerInstance) {
  std::string roots;
  write_binary(dir_ / "instances.glb", glb(test::wide_nodes(10, &roots), roots));  // 10 x 3 vertices
  import_limits().max_vertices = 29;
  EXPECT_NE(refusal(dir_ / "instances.glb").find("the glTF nodes place 30 vertices; a mesh file may hold at most 29"),
            std::string::npos)
      << refusal(dir_ / "instances.glb");
  import_limits().max_vertices = 30;
  EXPECT_EQ(refusal(dir_ / "instances.glb"), "");
}

TEST_F(FileBounds, AGltfGraphThatIsNotATreeIsRefused) {
  write_binary(dir_ / "cycle.glb", glb(R"([{"children":[1],"mesh":0},{"children":[0]}])", "[0]"));
  EXPECT_NE(refusal(dir_ / "cycle.glb").find("node 0 is reached twice"), std::string::npos) << refusal(dir_ / "cycle.glb");
  // A shared child: the walk would place it once per path, 2^n times down a ladder.
  write_binary(dir_ / "shared.glb", glb(R"([{"children":[1,2]},{"children":[2]},{"mesh":0}])", "[0]"));
  EXPECT_NE(refusal(dir_ / "shared.glb").find("node 2 is reached twice"), std::string::npos);
  // A cycle that no root leads to.
  write_binary(dir_ / "island.glb", glb(R"([{"mesh":0},{"children":[2]},{"children":[1]}])", "[0]"));
  EXPECT_NE(refusal(dir_ / "island.glb").find("is part of a cycle"), std::string::npos) << refusal(dir_ / "island.glb");
}

TEST_F(FileBounds, GltfJsonNestedDeeperThanTheFormatNeedsIsRefused) {
  const std::string deep = std::string(500, '[') + std::string(500, ']');
  write_binary(dir_ / "nested.glb", glb(R"([{"mesh":0,"extras":)" + deep + "}]", "[0]"));
  EXPECT_NE(refusal(dir_ / "nested.glb").find("JSON nested over 128 levels deep"), std::string::npos);
}

TEST_F(FileBounds, AnyFormatsGraphIsCheckedAfterParsingAndBeforePostProcessing) {
  // COLLADA: no pre-check reads its XML; the parsed graph is walked without recursion.
  std::string dae = R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">)"
                    R"(<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">)"
                    R"(0 0 0 1 0 0 0 1 0</float_array><technique_common><accessor source="#pa" count="3" stride="3">)"
                    R"(<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>)"
                    R"(</accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/>)"
                    R"(</vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p>)"
                    R"(</triangles></mesh></geometry></library_geometries><library_visual_scenes><visual_scene id="s">)";
  for (int i = 0; i < 300; ++i) dae += "<node id=\"n" + std::to_string(i) + "\">";
  dae += R"(<instance_geometry url="#g"/>)";
  for (int i = 0; i < 300; ++i) dae += "</node>";
  dae += R"(</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)";
  write_binary(dir_ / "deep.dae", dae);
  EXPECT_NE(refusal(dir_ / "deep.dae").find("the scene graph nests nodes over 256 levels deep"), std::string::npos)
      << refusal(dir_ / "deep.dae");
}

TEST_F(FileBounds, AnObjIsCountedAgainstTheLimits) {
  write_binary(dir_ / "grid.obj", test::grid_obj(10));  // 100 vertices, 162 faces
  import_limits().max_vertices = 99;
  EXPECT_NE(refusal(dir_ / "grid.obj").find("the OBJ file holds 100 vertices; a mesh file may hold at most 99"),
            std::string::npos);
  import_limits() = ImportLimits{};
  import_limits().max_triangles = 161;
  EXPECT_NE(refusal(dir_ / "grid.obj").find("the OBJ file holds 162 faces"), std::string::npos);
  import_limits().max_triangles = 162;
  EXPECT_EQ(refusal(dir_ / "grid.obj"), "");
}

TEST_F(FileBounds, AnObjCutInTheMiddleOfARecordIsRefusedAndAWholeLastLineIsNot) {
  for (const std::string cut : {"f 12/", "f 1 2", "v 0.5 0.25", "v 0.5 0.25 1.5e"}) {
    write_binary(dir_ / "cut.obj", test::grid_obj(10, "", cut));
    EXPECT_NE(refusal(dir_ / "cut.obj").find("the file is cut short: its last line '" + cut + "'"), std::string::npos)
        << cut << ": " << refusal(dir_ / "cut.obj");
  }
  // The same records whole, without a final newline (many exporters end so).
  write_binary(dir_ / "whole.obj", test::grid_obj(10, "", "f 1 2 11"));
  EXPECT_EQ(refusal(dir_ / "whole.obj"), "");
}

TEST_F(FileBounds, AnObjHoldingLessThanItsCommentsDeclareWarnsAndIsRead) {
  std::vector<std::string> warnings;
  const auto previous = set_warning_listener([&](const std::string& text) { warnings.push_back(text); });
  write_binary(dir_ / "short.obj", test::grid_obj(10, "# 2000000 faces\n"));
  EXPECT_EQ(refusal(dir_ / "short.obj"), "");
  write_binary(dir_ / "true.obj", test::grid_obj(10, "# Vertices: 100\n# Faces: 162\n"));
  EXPECT_EQ(refusal(dir_ / "true.obj"), "");
  set_warning_listener(previous);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("short.obj: its comments declare 0 vertices and 2,000,000 faces, and it holds 100 and 162"),
            std::string::npos)
      << warnings[0];
}

TEST_F(FileBounds, ABinaryStlIsHeldToItsHeadersCount) {
  std::string stl(80, ' ');
  stl += test::le32(3);
  for (int t = 0; t < 2; ++t) {  // Two of the three triangles.
    std::string facet(50, '\0');
    const float corners[9] = {0, 0, 0, 0.01f, 0, 0, 0, 0.01f, float(t) * 0.01f};
    std::memcpy(facet.data() + 12, corners, sizeof corners);
    stl += facet;
  }
  write_binary(dir_ / "cut.stl", stl);
  EXPECT_NE(refusal(dir_ / "cut.stl").find("the file is cut short: its header declares 3 triangles, 234 bytes, and it has 184"),
            std::string::npos)
      << refusal(dir_ / "cut.stl");
  import_limits().max_triangles = 2;
  EXPECT_NE(refusal(dir_ / "cut.stl").find("the STL header declares 3 faces"), std::string::npos);
}

}  // namespace
}  // namespace systole::mesh
