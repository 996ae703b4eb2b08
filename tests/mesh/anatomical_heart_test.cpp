// ctest-labels: slow-under-sanitizers
// The anatomical heart: hollow chambers in muscular walls, each cavity closed by its valve
// annuli, a volumetric myocardium whose surfaces and lattice agree, fibres where the muscle
// is, valves that can open, and the chambers where anatomy puts them.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

#include "mesh/anatomy.h"
#include "mesh/procedural.h"
#include "mesh/winding.h"

namespace systole::mesh {
namespace {

const OrganMesh& heart() {
  static const OrganMesh mesh = generate_organ("anatomical_heart", 3);
  return mesh;
}

Eigen::Vector3d part_centroid(const OrganMesh& m, const std::string& part) {
  const std::vector<char> in = m.part_mask(m.part_index(part));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t v = 0; v < in.size(); ++v) {
    if (in[v]) sum += m.surface.positions[v], ++count;
  }
  return sum / count;
}

TEST(AnatomicalHeart, EveryPartHasSurface) {
  const OrganMesh& m = heart();
  for (const std::string& part : m.part_names) {
    const std::vector<char> in = m.part_mask(m.part_index(part));
    EXPECT_GT(std::count(in.begin(), in.end(), 1), 10) << part;
  }
}

TEST(AnatomicalHeart, MuscleSurfaceIsClosedAndMatchesTheLatticeVolume) {
  const OrganMesh& m = heart();
  // Closed and consistently turned: every edge used once each way.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : m.anatomy.muscle) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
  double lattice = 0;
  for (std::size_t n = 0; n < m.anatomy.myocardium.nodes.size(); ++n) {
    if (m.anatomy.myocardium.node_volume_m3[n] > 0) lattice += m.anatomy.myocardium.node_volume_m3[n];
  }
  double six = 0;  // Signed: positive only if the surfaces face out of the muscle.
  for (const auto& t : m.anatomy.muscle) {
    six += m.surface.positions[t[0]].dot(m.surface.positions[t[1]].cross(m.surface.positions[t[2]]));
  }
  const double surfaces = six / 6;
  // The lattice includes the vessels' walls; the chamber walls are most of it.
  EXPECT_GT(surfaces, 0.75 * lattice);
  EXPECT_LT(surfaces, 1.05 * lattice);
  // An adult myocardium is about 150-250 ml (left ventricle alone 90-200 g at 1.05 g/ml).
  EXPECT_GT(surfaces, 150e-6);
  EXPECT_LT(surfaces, 300e-6);
}

TEST(AnatomicalHeart, CavitiesAreClosedByTheirAnnuliWithAdultVolumes) {
  const OrganMesh& m = heart();
  ASSERT_EQ(m.anatomy.cavities.size(), 4u);
  for (const Cavity& c : m.anatomy.cavities) {
    const double ml = cavity_volume(c, m.surface.positions) * 1e6;
    // End-diastolic volumes (Lang et al. 2015): ventricles 90-160 ml, atria 30-90 ml.
    const bool ventricle = c.name.find("ventricle") != std::string::npos;
    EXPECT_GT(ml, ventricle ? 90 : 30) << c.name;
    EXPECT_LT(ml, ventricle ? 160 : 90) << c.name;
  }
}

TEST(CavityVolume, CapsOpenRimsWhateverTheirSize) {
  // A unit cube's lining (facing in) with its top face missing: capped, it is 1 m^3.
  std::vector<Eigen::Vector3d> x;
  for (int i = 0; i < 8; ++i) x.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::vector<Eigen::Vector3i> outward = {{0, 2, 1}, {1, 2, 3}, {0, 1, 5}, {0, 5, 4}, {1, 3, 7}, {1, 7, 5},
                                                {3, 2, 6}, {3, 6, 7}, {2, 0, 4}, {2, 4, 6}};  // No top (z = 1).
  Cavity c{"box", {}, {}};
  for (const auto& t : outward) c.lining.emplace_back(t[0], t[2], t[1]);  // Facing into the box.
  find_rims(c);
  ASSERT_EQ(c.rims.size(), 1u);
  EXPECT_EQ(c.rims[0].size(), 4u);
  EXPECT_NEAR(cavity_volume(c, x), 1.0, 1e-12);
  x[4].z() = x[5].z() = x[6].z() = x[7].z() = 3;  // Taller: the cap moves with its rim.
  EXPECT_NEAR(cavity_volume(c, x), 3.0, 1e-12);
}

// Each wall's outside is one closed surface, and every lining vertex lies inside the walls'
// outside at rest, at every detail: the right ventricle's crescent once ended at the ray
// from its axis tangent to the left wall's outside, in a cliff with no wall between lining
// and outside (docs/anatomy.md, "The wall keeps its lining inside").
TEST(AnatomicalHeart, EveryLiningLiesInsideTheEpicardiumAtRest) {
  for (int detail = 1; detail <= 6; ++detail) {
    const OrganMesh m = detail == 3 ? heart() : generate_organ("anatomical_heart", detail);
    const std::vector<Eigen::Vector3i> outside = epicardium(m.anatomy);
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : outside) {
      for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : edges) {
      ASSERT_EQ(count, 1) << "detail " << detail;
      ASSERT_EQ(edges.count({edge.second, edge.first}), 1u) << "detail " << detail;
    }
    const std::vector<int> lining = lining_vertices(m.anatomy);
    ASSERT_GT(lining.size(), 100u);
    Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(m.surface.positions.size())), points(3, static_cast<Eigen::Index>(lining.size()));
    for (std::size_t v = 0; v < m.surface.positions.size(); ++v) x.col(static_cast<Eigen::Index>(v)) = m.surface.positions[v];
    for (std::size_t i = 0; i < lining.size(); ++i) points.col(static_cast<Eigen::Index>(i)) = x.col(lining[i]);
    const std::vector<int> winding = winding_numbers(x, outside, points);
    for (std::size_t i = 0; i < lining.size(); ++i) {
      EXPECT_GE(winding[i], 1) << "detail " << detail << ": lining vertex " << lining[i] << " outside the epicardium";
    }
  }
}

TEST(AnatomicalHeart, FibresOnlyInTheMuscleAndPerpendicularToTheWall) {
  const Myocardium& myo = heart().anatomy.myocardium;
  ASSERT_EQ(myo.fibre_share.size(), myo.springs.size());
  int active = 0, passive = 0;
  for (std::size_t j = 0; j < myo.springs.size(); ++j) {
    if (myo.fibre_share[j] < 0) {
      ++passive;
      continue;
    }
    ++active;
    // The fibre lies in the wall, so a direction's shares along it and across the wall sum to at most 1.
    EXPECT_LE(myo.fibre_share[j] + myo.normal_share[j], 1.0 + 1e-9) << j;
    EXPECT_GE(myo.fibre_share[j], 0.0);
  }
  EXPECT_GT(active, 10 * passive / 2);  // Vessels and glue are the small rest.
  EXPECT_GT(passive, 0);
}

TEST(AnatomicalHeart, DrawnVerticesFollowNearbyNodes) {
  const OrganMesh& m = heart();
  const Myocardium& myo = m.anatomy.myocardium;
  ASSERT_EQ(myo.vertex_nodes.size(), m.surface.positions.size());
  for (std::size_t v = 0; v < m.surface.positions.size(); ++v) {
    double sum = 0;
    Eigen::Vector3d carried = Eigen::Vector3d::Zero();
    for (int k = 0; k < 8; ++k) sum += myo.vertex_weights[v][k], carried += myo.vertex_weights[v][k] * myo.nodes[myo.vertex_nodes[v][k]];
    EXPECT_NEAR(sum, 1.0, 1e-9) << v;
    // A valve leaflet reaches across its annulus; everything else lies in its cell.
    EXPECT_LT((carried - m.surface.positions[v]).norm(), 0.03) << v;
  }
}

TEST(AnatomicalHeart, ValvesOpenDownstream) {
  const OrganMesh& m = heart();
  ASSERT_EQ(m.anatomy.valves.size(), 4u);
  for (const Valve& valve : m.anatomy.valves) {
    ASSERT_EQ(valve.open_positions.size(), valve.vertices.size()) << valve.name;
    double moved = 0;
    for (std::size_t i = 0; i < valve.vertices.size(); ++i) moved += (valve.open_positions[i] - m.surface.positions[valve.vertices[i]]).norm();
    EXPECT_GT(moved / valve.vertices.size(), 0.004) << valve.name;  // Leaflets swing millimetres, not microns.
  }
}

TEST(AnatomicalHeart, ChambersWhereAnatomyPutsThem) {
  const OrganMesh& m = heart();
  // +X the patient's left, +Y up, +Z anterior.
  EXPECT_GT(part_centroid(m, "right_ventricle").z(), part_centroid(m, "left_ventricle").z());  // RV in front,
  EXPECT_LT(part_centroid(m, "right_atrium").x(), part_centroid(m, "left_atrium").x());       // RA to the right,
  EXPECT_LT(part_centroid(m, "left_atrium").z(), part_centroid(m, "right_ventricle").z());    // LA behind,
  EXPECT_LT(part_centroid(m, "apex").y(), part_centroid(m, "left_atrium").y());               // apex down
  EXPECT_GT(part_centroid(m, "apex").x(), part_centroid(m, "right_atrium").x());              // and to the left.
  EXPECT_GT(part_centroid(m, "aorta").y(), part_centroid(m, "left_ventricle").y());
  // The left ventricle's wall is thicker than the right's (about 10 mm against 4).
  const VentricleLandmarks& lv = m.anatomy.left_ventricle;
  double thickness = 0;
  for (const auto& [inner, outer] : lv.wall) thickness += (m.surface.positions[outer] - m.surface.positions[inner]).norm();
  thickness /= lv.wall.size();
  EXPECT_GT(thickness, 0.008);
  EXPECT_LT(thickness, 0.013);
}

}  // namespace
}  // namespace systole::mesh
