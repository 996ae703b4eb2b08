#include "mesh/inspect.h"

#include <gtest/gtest.h>

#include "mesh/icosphere.h"
#include "mesh/weld.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

bool notes_mention(const MeshReport& r, const std::string& word) {
  for (const auto& n : r.notes) {
    if (n.find(word) != std::string::npos) return true;
  }
  return false;
}

TEST(Inspect, CubeIsClean) {
  const MeshReport r = inspect(testing::cube());
  EXPECT_TRUE(r.clean());
  EXPECT_EQ(r.components, 1);
  EXPECT_NEAR(r.volume_m3, 1.0, 1e-12);
  EXPECT_TRUE(r.notes.empty());
}

TEST(Inspect, OpenMeshHasBoundaryEdges) {
  TriangleMesh m = testing::cube();
  m.triangles.pop_back();
  const MeshReport r = inspect(m);
  EXPECT_EQ(r.boundary_edges, 3);
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.encloses_volume());
  EXPECT_TRUE(notes_mention(r, "open surface"));
  EXPECT_TRUE(notes_mention(r, "volume constraint is disabled"));
  EXPECT_TRUE(notes_mention(r, ") m"));  // An example location.
}

TEST(Inspect, NonManifoldFan) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // Three triangles on edge 0-1.
  const MeshReport r = inspect(m);
  EXPECT_EQ(r.nonmanifold_edges, 1);
  EXPECT_FALSE(r.closed());
  EXPECT_TRUE(notes_mention(r, "non-manifold"));
}

TEST(Inspect, FlippedTriangle) {
  TriangleMesh m = testing::tetrahedron();
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const MeshReport r = inspect(m);
  EXPECT_EQ(r.inconsistent_edges, 3);
  EXPECT_TRUE(r.closed());
  EXPECT_FALSE(r.clean());
  EXPECT_TRUE(notes_mention(r, "inconsistent orientation"));
}

TEST(Inspect, TwoPieces) {
  TriangleMesh m = testing::cube();
  const TriangleMesh t = testing::tetrahedron();
  const int base = static_cast<int>(m.positions.size());
  for (const auto& p : t.positions) m.positions.push_back(p + Eigen::Vector3d(5, 0, 0));
  for (const auto& f : t.triangles) m.triangles.push_back(f + Eigen::Vector3i::Constant(base));
  const MeshReport r = inspect(m);
  EXPECT_EQ(r.components, 2);
  EXPECT_TRUE(r.clean());
  EXPECT_NEAR(r.volume_m3, 1.0 + 8.0 / 3.0, 1e-9);
  EXPECT_TRUE(notes_mention(r, "separate pieces"));
}

TEST(Inspect, DegenerateTriangles) {
  TriangleMesh m = testing::cube();
  m.positions.emplace_back(0.5, 0.5, 0.5);
  m.positions.emplace_back(1.5, 1.5, 1.5);
  m.triangles.emplace_back(0, 8, 9);  // Collinear corners.
  m.triangles.emplace_back(1, 1, 2);  // Repeated index.
  const MeshReport r = inspect(m);
  EXPECT_EQ(r.degenerate_triangles, 2);
  EXPECT_TRUE(notes_mention(r, "degenerate"));
}

TEST(Inspect, NeverCrashesOnBadInput) {
  EXPECT_EQ(inspect(TriangleMesh{}).triangles, 0);
  EXPECT_FALSE(inspect(TriangleMesh{}).closed());

  TriangleMesh single;
  single.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  single.triangles = {{0, 1, 2}};
  const MeshReport one = inspect(single);
  EXPECT_EQ(one.boundary_edges, 3);
  EXPECT_EQ(one.components, 1);

  TriangleMesh broken = single;
  broken.triangles.emplace_back(0, 1, 7);
  broken.triangles.emplace_back(-1, 0, 1);
  broken.positions.emplace_back(std::nan(""), 0, 0);
  broken.triangles.emplace_back(0, 1, 3);
  const MeshReport r = inspect(broken);
  EXPECT_EQ(r.invalid_triangles, 3);
  EXPECT_EQ(r.boundary_edges, 3);
  EXPECT_FALSE(r.clean());
  EXPECT_TRUE(notes_mention(r, "invalid triangles"));
}

TEST(Weld, SplitCubeBecomesClosed) {
  // Every triangle with its own three vertices, as STL stores them.
  const TriangleMesh cube = testing::cube();
  OrganMesh split;
  for (const auto& t : cube.triangles) {
    const int base = static_cast<int>(split.surface.positions.size());
    for (int k = 0; k < 3; ++k) split.surface.positions.push_back(cube.positions[t[k]] + Eigen::Vector3d::Constant(1e-9 * k));
    split.surface.triangles.emplace_back(base, base + 1, base + 2);
    split.vertex_part.insert(split.vertex_part.end(), 3, 0);
  }
  split.part_names = {"cube"};
  EXPECT_FALSE(inspect(split.surface).closed());
  const int removed = weld(split, default_weld_tolerance(split.surface) * 1000);
  EXPECT_EQ(removed, 36 - 8);
  EXPECT_EQ(split.surface.positions.size(), 8u);
  EXPECT_EQ(split.vertex_part.size(), 8u);
  EXPECT_TRUE(inspect(split.surface).clean());
}

TEST(Weld, DropsCollapsedTrianglesAndIsDeterministic) {
  OrganMesh m;
  m.surface.positions = {{0, 0, 0}, {1, 0, 0}, {1e-9, 0, 0}, {0, 1, 0}};
  m.surface.triangles = {{0, 1, 3}, {0, 2, 3}};
  OrganMesh copy = m;
  EXPECT_EQ(weld(m, 1e-6), 1);
  EXPECT_EQ(m.surface.triangles.size(), 1u);
  weld(copy, 1e-6);
  EXPECT_EQ(m.surface.positions, copy.surface.positions);
  EXPECT_EQ(m.surface.triangles, copy.surface.triangles);
}

TEST(Weld, ToleranceIsRelativeToSize) {
  for (double scale : {1e-8, 1.0, 1e8}) {
    TriangleMesh m = testing::cube();
    for (auto& p : m.positions) p *= scale;
    EXPECT_NEAR(default_weld_tolerance(m), 1e-6 * std::sqrt(3.0) * scale, 1e-9 * scale);
    OrganMesh organ{m, {"cube"}, std::vector<int>(8, 0)};
    EXPECT_EQ(weld(organ, default_weld_tolerance(m)), 0);
    EXPECT_TRUE(inspect(organ.surface).clean());
  }
}

}  // namespace
}  // namespace systole::mesh

namespace systole::mesh {
namespace {

TEST(Inspect, ClosedOutwardPiecesAreMarkedPerVertex) {
  // A ball (closed, outward), an inside-out ball and an open sheet, as one mesh.
  const TriangleMesh ball = icosphere(0.02, 1);
  TriangleMesh m = ball;
  const auto append = [&](const TriangleMesh& piece, const Eigen::Vector3d& offset, bool flip) {
    const int first = static_cast<int>(m.positions.size());
    for (const auto& p : piece.positions) m.positions.push_back(p + offset);
    for (const auto& t : piece.triangles) {
      m.triangles.push_back(Eigen::Vector3i(t[0], flip ? t[2] : t[1], flip ? t[1] : t[2]) + Eigen::Vector3i::Constant(first));
    }
  };
  append(ball, Eigen::Vector3d(0.1, 0, 0), true);
  TriangleMesh sheet;
  sheet.positions = {{0, 0, 0.1}, {0.01, 0, 0.1}, {0, 0.01, 0.1}};
  sheet.triangles = {{0, 1, 2}};
  append(sheet, Eigen::Vector3d::Zero(), false);
  const MeshReport r = inspect(m);
  ASSERT_EQ(r.in_closed_piece.size(), m.positions.size());
  const std::size_t n = ball.positions.size();
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_EQ(r.in_closed_piece[v] != 0, v < n) << "vertex " << v << (v < n ? " of the ball" : v < 2 * n ? " of the inside-out ball" : " of the sheet");
  }
}

}  // namespace
}  // namespace systole::mesh
