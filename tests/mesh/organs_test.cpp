// ctest-labels: slow-under-sanitizers
// Every procedural organ besides the heart (heart_test.cpp): closed, manifold, outward,
// well-shaped, every vertex in exactly one named part, at several levels of detail; plus
// each organ's anatomy (size, orientation, where its parts are).

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <tuple>

#include "mesh/inspect.h"
#include "mesh/normals.h"
#include "mesh/procedural.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

struct Expected {
  const char* organ;
  std::vector<std::string> parts;
  int components;
  double min_volume_m3, max_volume_m3;
};

const std::vector<Expected>& expectations() {
  static const std::vector<Expected> all = {
      {"lungs",
       {"right_upper_lobe", "right_middle_lobe", "right_lower_lobe", "left_upper_lobe", "left_lower_lobe", "trachea"},
       5, 2.5e-3, 6e-3},  // Two lungs, and the trachea and two main bronchi overlapping at the carina.
      {"kidney", {"upper_pole", "interpolar", "lower_pole", "hilum"}, 1, 100e-6, 250e-6},
      {"liver", {"right_lobe", "left_lobe", "gallbladder", "inferior_vena_cava"}, 1, 1.2e-3, 2.6e-3},
  };
  return all;
}

class OrganAtDetail : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(OrganAtDetail, IsAClosedWellShapedSurfaceWithAllParts) {
  const Expected& e = expectations()[static_cast<size_t>(std::get<0>(GetParam()))];
  const int detail = std::get<1>(GetParam());
  const auto start = std::chrono::steady_clock::now();
  const OrganMesh organ = generate_organ(e.organ, detail);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TriangleMesh& s = organ.surface;

  const MeshReport r = inspect(s);
  EXPECT_TRUE(r.clean()) << (r.notes.empty() ? "" : r.notes.front());
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.nonmanifold_edges, 0);
  EXPECT_EQ(r.inconsistent_edges, 0);
  EXPECT_EQ(r.degenerate_triangles, 0);
  EXPECT_EQ(r.unused_vertices, 0);
  EXPECT_EQ(r.components, e.components);
  EXPECT_GT(r.volume_m3, e.min_volume_m3);  // Positive: outward.
  EXPECT_LT(r.volume_m3, e.max_volume_m3);
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

  // Parts: the expected names, every vertex in exactly one, none empty.
  ASSERT_EQ(organ.part_names, e.parts);
  ASSERT_EQ(organ.vertex_part.size(), s.positions.size());
  std::vector<int> count(organ.part_names.size(), 0);
  for (int part : organ.vertex_part) {
    ASSERT_GE(part, 0);
    ASSERT_LT(part, static_cast<int>(count.size()));
    ++count[static_cast<size_t>(part)];
  }
  for (size_t p = 0; p < count.size(); ++p) EXPECT_GT(count[p], 0) << organ.part_names[p];

  std::printf("[ %-8s ] detail %d: %zu triangles, %zu vertices, min angle %.1f deg, %.0f ml, %.3f s\n", e.organ, detail,
              s.triangles.size(), s.positions.size(), min_angle, r.volume_m3 * 1e6, seconds);
}

INSTANTIATE_TEST_SUITE_P(Details, OrganAtDetail, ::testing::Combine(::testing::Range(0, 3), ::testing::Values(1, 2, 3, 4, 5)),
                         [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
                           return std::string(expectations()[static_cast<size_t>(std::get<0>(info.param))].organ) +
                                  "_detail" + std::to_string(std::get<1>(info.param));
                         });

TEST(Organs, TriangleCountGrowsWithDetailAndIsDeterministic) {
  for (const Expected& e : expectations()) {
    size_t previous = 0;
    for (int detail = 1; detail <= 4; ++detail) {
      const size_t count = generate_organ(e.organ, detail).surface.triangles.size();
      // About doubles; at least x1.3 (the lungs' airway keeps one resolution at every detail).
      EXPECT_GT(count, previous * 13 / 10) << e.organ << " detail " << detail;
      previous = count;
    }
    const OrganMesh a = generate_organ(e.organ, 2), b = generate_organ(e.organ, 2);
    EXPECT_EQ(a.surface.positions, b.surface.positions) << e.organ;  // Bit for bit.
    EXPECT_EQ(a.surface.triangles, b.surface.triangles) << e.organ;
    EXPECT_EQ(a.vertex_part, b.vertex_part) << e.organ;
  }
}

// Centroid and bounding box of a part's vertices (or of all, for "").
struct Extent {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), lo, hi;
  int count = 0;
};

Extent extent(const OrganMesh& m, const std::string& part) {
  Extent e;
  e.lo = Eigen::Vector3d::Constant(1e9), e.hi = -e.lo;
  const int index = part.empty() ? -2 : m.part_index(part);
  for (size_t v = 0; v < m.surface.positions.size(); ++v) {
    if (index != -2 && m.vertex_part[v] != index) continue;
    const Eigen::Vector3d& p = m.surface.positions[v];
    e.centroid += p, ++e.count, e.lo = e.lo.cwiseMin(p), e.hi = e.hi.cwiseMax(p);
  }
  e.centroid /= std::max(e.count, 1);
  return e;
}

TEST(Lungs, AnatomyAndSize) {
  const OrganMesh m = generate_organ("lungs", 3);
  const Extent all = extent(m, "");
  const Eigen::Vector3d size = all.hi - all.lo;
  EXPECT_GT(size.y(), 0.22);  // About 25 cm from the base to the top of the tracheal stub.
  EXPECT_LT(size.y(), 0.30);
  EXPECT_GT(size.x(), 0.22);
  EXPECT_LT(size.x(), 0.32);
  EXPECT_LT(std::abs(all.centroid.x()), 0.03);  // Centred near the origin.
  EXPECT_LT(std::abs(all.centroid.y()), 0.05);
  // Right lung at -X, left at +X; the trachea on top in the middle.
  for (const char* right : {"right_upper_lobe", "right_middle_lobe", "right_lower_lobe"}) EXPECT_LT(extent(m, right).hi.x(), 0);
  for (const char* left : {"left_upper_lobe", "left_lower_lobe"}) EXPECT_GT(extent(m, left).lo.x(), 0);
  const Extent trachea = extent(m, "trachea");
  EXPECT_GT(trachea.hi.y(), extent(m, "right_upper_lobe").hi.y());
  // Upper lobes above, lower lobes behind and below; the middle lobe in front, low.
  EXPECT_GT(extent(m, "right_upper_lobe").centroid.y(), extent(m, "right_middle_lobe").centroid.y());
  EXPECT_GT(extent(m, "right_middle_lobe").centroid.z(), extent(m, "right_lower_lobe").centroid.z());
  EXPECT_LT(extent(m, "left_lower_lobe").centroid.z(), extent(m, "left_upper_lobe").centroid.z());
  // The left lung is the smaller: fewer of the evenly sized triangles' vertices.
  const int right = extent(m, "right_upper_lobe").count + extent(m, "right_middle_lobe").count +
                    extent(m, "right_lower_lobe").count;
  const int left = extent(m, "left_upper_lobe").count + extent(m, "left_lower_lobe").count;
  EXPECT_LT(left, right);
}

TEST(Kidney, AnatomyAndSize) {
  const OrganMesh m = generate_organ("kidney", 3);
  const Extent all = extent(m, "");
  const Extent body = [&] {  // Without the stubs.
    Extent e = extent(m, "upper_pole");
    e.lo = e.lo.cwiseMin(extent(m, "lower_pole").lo), e.hi = e.hi.cwiseMax(extent(m, "lower_pole").hi);
    return e;
  }();
  EXPECT_GT(body.hi.y() - body.lo.y(), 0.10);  // About 11 cm long,
  EXPECT_LT(body.hi.y() - body.lo.y(), 0.125);
  EXPECT_GT(all.hi.z() - all.lo.z(), 0.03);     // 3-5 cm thick.
  EXPECT_LT(all.hi.z() - all.lo.z(), 0.05);
  EXPECT_GT(extent(m, "upper_pole").centroid.y(), extent(m, "lower_pole").centroid.y());
  // The hilum faces the midline (-X) and sits between the poles.
  const Extent hilum = extent(m, "hilum");
  EXPECT_LT(hilum.centroid.x(), extent(m, "interpolar").centroid.x());
  EXPECT_LT(hilum.centroid.y(), extent(m, "upper_pole").centroid.y());
  EXPECT_GT(hilum.centroid.y(), extent(m, "lower_pole").centroid.y());
}

TEST(Liver, AnatomyAndSize) {
  const OrganMesh m = generate_organ("liver", 3);
  const Extent all = extent(m, "");
  EXPECT_GT(all.hi.x() - all.lo.x(), 0.19);  // About 20-23 cm wide.
  EXPECT_LT(all.hi.x() - all.lo.x(), 0.25);
  const Extent right = extent(m, "right_lobe"), left = extent(m, "left_lobe");
  EXPECT_LT(right.centroid.x(), left.centroid.x());  // The right lobe on the patient's right (-X),
  EXPECT_GT(right.hi.y() - right.lo.y(), left.hi.y() - left.lo.y());  // and the taller.
  EXPECT_GT(right.count, left.count);
  EXPECT_LT(extent(m, "gallbladder").centroid.y(), right.centroid.y());  // Below,
  EXPECT_GT(extent(m, "gallbladder").centroid.z(), 0.0);                 // in front.
  EXPECT_LT(extent(m, "inferior_vena_cava").centroid.z(), 0.0);          // The IVC behind.
}

TEST(Organs, KnownNames) {
  const std::vector<std::string> names = procedural_organs();
  for (const char* name : {"heart", "lungs", "kidney", "liver"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
}

}  // namespace
}  // namespace systole::mesh
