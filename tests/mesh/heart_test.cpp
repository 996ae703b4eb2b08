// ctest-labels: slow-under-sanitizers
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "common/error.h"
#include "mesh/inspect.h"
#include "mesh/normals.h"
#include "mesh/procedural.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

const char* const kHeartParts[] = {"left_ventricle", "right_ventricle", "left_atrium",
                                   "right_atrium",   "apex",            "aorta",
                                   "pulmonary_trunk", "superior_vena_cava", "inferior_vena_cava"};

class HeartAtDetail : public ::testing::TestWithParam<int> {};

TEST_P(HeartAtDetail, IsAClosedWellShapedSurfaceWithAllParts) {
  const int detail = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const OrganMesh heart = generate_organ("heart", detail);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TriangleMesh& s = heart.surface;

  const MeshReport r = inspect(s);
  EXPECT_TRUE(r.clean()) << (r.notes.empty() ? "" : r.notes.front());
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.nonmanifold_edges, 0);
  EXPECT_EQ(r.inconsistent_edges, 0);
  EXPECT_EQ(r.degenerate_triangles, 0);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.unused_vertices, 0);
  EXPECT_GT(r.volume_m3, 0);
  // A heart of about 12 cm by 8-9 cm holds a few hundred millilitres.
  EXPECT_GT(r.volume_m3, 250e-6);
  EXPECT_LT(r.volume_m3, 700e-6);

  const double min_angle = testing::min_angle_deg(s);
  EXPECT_GT(min_angle, 10.0);

  // No folds: each triangle faces the same way as the vertex normals at its corners.
  std::vector<double> xyz;
  for (const auto& p : s.positions) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  std::vector<float> n(xyz.size());
  vertex_normals(xyz.data(), static_cast<int>(s.positions.size()), s.triangles, n.data());
  int folded = 0;
  for (const auto& t : s.triangles) {
    const Eigen::Vector3d fn = (s.positions[t[1]] - s.positions[t[0]]).cross(s.positions[t[2]] - s.positions[t[0]]);
    for (int k = 0; k < 3; ++k) folded += fn.dot(Eigen::Vector3d(n[3 * t[k]], n[3 * t[k] + 1], n[3 * t[k] + 2])) <= 0;
  }
  EXPECT_EQ(folded, 0);

  // Parts: the nine names, every vertex in exactly one, none empty.
  ASSERT_EQ(heart.part_names.size(), std::size(kHeartParts));
  for (const char* name : kHeartParts) EXPECT_GE(heart.part_index(name), 0) << name;
  ASSERT_EQ(heart.vertex_part.size(), s.positions.size());
  std::vector<int> count(heart.part_names.size(), 0);
  for (int part : heart.vertex_part) {
    ASSERT_GE(part, 0);
    ASSERT_LT(part, static_cast<int>(count.size()));
    ++count[static_cast<size_t>(part)];
  }
  for (size_t p = 0; p < count.size(); ++p) EXPECT_GT(count[p], 0) << heart.part_names[p];

  std::printf("[ heart    ] detail %d: %zu triangles, %zu vertices, min angle %.1f deg, %.0f ml, %.3f s\n", detail,
              s.triangles.size(), s.positions.size(), min_angle, r.volume_m3 * 1e6, seconds);
}

INSTANTIATE_TEST_SUITE_P(Details, HeartAtDetail, ::testing::Range(1, 7));

TEST(Heart, TriangleCountGrowsWithDetail) {
  size_t previous = 0;
  for (int detail = 1; detail <= 6; ++detail) {
    const size_t count = generate_organ("heart", detail).surface.triangles.size();
    EXPECT_GT(count, previous * 3 / 2) << "detail " << detail;
    previous = count;
  }
}

TEST(Heart, Deterministic) {
  const OrganMesh a = generate_organ("heart", 3);
  const OrganMesh b = generate_organ("heart", 3);
  EXPECT_EQ(a.surface.positions, b.surface.positions);  // Bit for bit.
  EXPECT_EQ(a.surface.triangles, b.surface.triangles);
  EXPECT_EQ(a.vertex_part, b.vertex_part);
}

TEST(Heart, AnatomicalOrientationAndSize) {
  const OrganMesh heart = generate_organ("heart", 3);
  auto centroid = [&](const char* part) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (size_t v = 0; v < heart.vertex_part.size(); ++v) {
      if (heart.vertex_part[v] == heart.part_index(part)) sum += heart.surface.positions[v], ++n;
    }
    return Eigen::Vector3d(sum / n);
  };
  const Eigen::Vector3d apex = centroid("apex"), aorta = centroid("aorta");
  const Eigen::Vector3d la = centroid("left_atrium"), ra = centroid("right_atrium");
  const Eigen::Vector3d lv = centroid("left_ventricle"), rv = centroid("right_ventricle");
  EXPECT_LT(apex.y(), lv.y());  // Apex down,
  EXPECT_GT(apex.z(), la.z());  // forward,
  EXPECT_GT(apex.x(), ra.x());  // and to the patient's left (+X).
  EXPECT_GT(aorta.y(), lv.y());  // Vessels on top.
  EXPECT_GT(lv.x(), rv.x());     // Left ventricle on the left.
  EXPECT_GT(rv.z(), la.z());     // Right ventricle in front.
  EXPECT_GT(la.x(), ra.x());
  EXPECT_GT(centroid("superior_vena_cava").y(), centroid("inferior_vena_cava").y());

  // Size: the chambers (apex to atria) span about 12 cm; the width is 8-9 cm.
  Eigen::Vector3d lo = heart.surface.positions.front(), hi = lo;
  for (const auto& p : heart.surface.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_GT(hi.x() - lo.x(), 0.075);
  EXPECT_LT(hi.x() - lo.x(), 0.11);
  EXPECT_GT(hi.y() - lo.y(), 0.11);
  EXPECT_LT(hi.y() - lo.y(), 0.17);
}

TEST(Heart, RejectsUnknownNameAndDetail) {
  EXPECT_THROW(generate_organ("spleen", 3), Error);
  EXPECT_THROW(generate_organ("heart", 0), Error);
  EXPECT_THROW(generate_organ("heart", 7), Error);
  try {
    generate_organ("spleen", 3);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("heart"), std::string::npos);  // Lists the known organs.
  }
  EXPECT_FALSE(procedural_organs().empty());
}

}  // namespace
}  // namespace systole::mesh
