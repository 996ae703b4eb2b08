// Every part's surface at once (mesh::OrganMesh::part_surfaces): the same triangles as each
// part's own surface, over the part's vertices only, whatever the membership.

#include <gtest/gtest.h>

#include <random>

#include "mesh/inspect.h"
#include "mesh/mesh.h"

namespace systole::mesh {
namespace {

/// `parts` tetrahedra in a row, each its own part; tetrahedron k also belongs to part k + 1
/// by one shared vertex, so the membership has pairs, and the last vertex belongs to none.
OrganMesh tetrahedra(int parts) {
  OrganMesh m;
  for (int k = 0; k < parts; ++k) {
    const int base = static_cast<int>(m.surface.positions.size());
    const double x = 2.0 * k;
    m.surface.positions.insert(m.surface.positions.end(),
                               {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    m.surface.triangles.insert(m.surface.triangles.end(), {{base, base + 2, base + 1}, {base, base + 1, base + 3},
                                                           {base, base + 3, base + 2}, {base + 1, base + 2, base + 3}});
    m.part_names.push_back("part" + std::to_string(k));
    m.vertex_part.insert(m.vertex_part.end(), {k, k, k, k});
    if (k + 1 < parts) m.also_in.push_back({base, k + 1});
  }
  m.surface.positions.push_back({-5, -5, -5});
  m.vertex_part.push_back(-1);
  m.normalize_membership();
  return m;
}

/// A part's surface over its own vertices, compared as triangles of positions.
std::vector<std::array<Eigen::Vector3d, 3>> corners(const TriangleMesh& m) {
  std::vector<std::array<Eigen::Vector3d, 3>> out;
  for (const auto& t : m.triangles) out.push_back({m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]});
  return out;
}

TEST(PartSurfaces, EachIsThePartsOwnSurfaceOverItsOwnVertices) {
  const OrganMesh m = tetrahedra(40);
  const std::vector<TriangleMesh> all = m.part_surfaces();
  ASSERT_EQ(all.size(), m.part_names.size());
  for (std::size_t p = 0; p < all.size(); ++p) {
    const TriangleMesh one = m.part_surface(static_cast<int>(p));
    EXPECT_EQ(corners(all[p]), corners(one)) << "part " << p;
    EXPECT_EQ(all[p].positions.size(), 4u) << "its own vertices only";
    const MeshReport a = inspect(all[p]), b = inspect(one);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_TRUE(a.closed()) << "part " << p;
    EXPECT_EQ(a.closed(), b.closed());
  }
}

TEST(PartSurfaces, ATriangleInTwoPartsIsInBothAndOneInNoneInNeither) {
  OrganMesh m;
  m.surface.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  m.surface.triangles = {{0, 1, 2}, {0, 1, 3}};
  m.part_names = {"wall", "ring"};
  m.vertex_part = {0, 0, 0, -1};
  m.also_in = {{0, 1}, {1, 1}, {2, 1}, {2, 1}};  // Not normalized: a pair repeats.
  const std::vector<TriangleMesh> all = m.part_surfaces();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].triangles.size(), 1u);
  EXPECT_EQ(all[1].triangles.size(), 1u) << "once, though a pair repeats";
  EXPECT_EQ(all[1].positions.size(), 3u);
}

}  // namespace
}  // namespace systole::mesh
