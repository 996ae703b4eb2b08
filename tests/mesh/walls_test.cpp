// The anatomical heart's wall builder (mesh/procedural/walls.h) on the simplest wall it
// builds, a straight vessel: its points lie at the lining's and the outside's radius, its
// frame is orthonormal and radial, its lattice holds the wall's volume exactly (a prism over
// the polygon of its columns), its cell springs weigh 1 on average, carriers interpolate,
// and its drawn lining and outside face out of the wall.

#include "mesh/procedural/walls.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace systole::mesh::procedural {
namespace {

constexpr double kR = 0.012, kT = 0.003, kL = 0.04;  // Lining radius, wall, length. unit: m

WallShape tube() {
  WallShape w;
  w.tube = true;
  w.origin = Vec::Zero();
  w.axis = Vec::UnitZ();
  w.e1 = Vec::UnitX();
  w.e2 = Vec::UnitY();
  w.height = {0, -kL};
  w.radius = {kR, kR};
  w.thickness = {kT, kT};
  w.columns = 12;
  w.rows_per_key = 2;
  w.layers = 2;
  w.draw_columns = 24;
  w.draw_rows_per_key = 4;
  return w;
}

double from_axis(const Vec& x) { return std::hypot(x.x(), x.y()); }

struct Built {
  HeartBuilder builder{{"aorta"}};
  Wall wall{builder, tube(), [](const WallPoint&, bool) { return std::vector<int>{0}; }};
};

TEST(Walls, PointsLieBetweenTheLiningAndTheOutside) {
  Built b;
  for (double around : {0.0, 1.0, 2.5, 5.9}) {
    for (double along : {0.0, 0.3, 1.0}) {
      EXPECT_NEAR(from_axis(b.wall.point({around, along, 0})), kR, 1e-12);
      EXPECT_NEAR(from_axis(b.wall.point({around, along, 1})), kR + kT, 1e-12);
      EXPECT_NEAR(from_axis(b.wall.point({around, along, 0.5})), kR + 0.5 * kT, 1e-12);
      EXPECT_NEAR(b.wall.point({around, along, 0.5}).z(), -kL * along, 1e-12);
    }
    // Around 0 lies along e1; a quarter turn along e2.
  }
  EXPECT_NEAR(b.wall.point({0, 0.5, 0}).y(), 0.0, 1e-12);
  EXPECT_GT(b.wall.point({0, 0.5, 0}).x(), 0.0);
  EXPECT_NEAR(b.wall.point({std::numbers::pi / 2, 0.5, 0}).x(), 0.0, 1e-12);
  EXPECT_NEAR(b.wall.lining_radius(1.0, 0.5), kR, 1e-12);
  EXPECT_NEAR(b.wall.outside_radius_at(-0.5 * kL, 0.0), kR + kT, 1e-9);
  EXPECT_EQ(b.wall.outside_radius_at(0.5 * kL, 0.0), 0.0);  // The tube does not reach that plane.
}

TEST(Walls, TheFrameIsOrthonormalWithTheNormalPointingOut) {
  Built b;
  for (double around : {0.2, 3.0}) {
    const WallPoint p{around, 0.4, 0.5};
    Vec circumferential, meridian, normal;
    b.wall.frame(p, circumferential, meridian, normal);
    EXPECT_NEAR(circumferential.norm(), 1.0, 1e-12);
    EXPECT_NEAR(meridian.norm(), 1.0, 1e-12);
    EXPECT_NEAR(normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(circumferential.dot(meridian), 0.0, 1e-12);
    EXPECT_NEAR(circumferential.dot(normal), 0.0, 1e-12);
    EXPECT_NEAR(meridian.dot(normal), 0.0, 1e-12);
    const Vec x = b.wall.point(p);
    EXPECT_TRUE(normal.isApprox(Vec(x.x(), x.y(), 0).normalized(), 1e-9));  // Radial, outward.
    EXPECT_NEAR(std::abs(meridian.z()), 1.0, 1e-12);                        // Along the axis.
  }
}

TEST(Walls, TheLatticeHoldsTheWallsVolumeAndItsCellSpringsWeighOneOnAverage) {
  Built b;
  const OrganMesh mesh = b.builder.finish();
  const Myocardium& m = mesh.anatomy.myocardium;
  // 2 layers x 2 rows x 12 columns of cells, over (layers + 1) x (rows + 1) x 12 nodes.
  EXPECT_EQ(m.nodes.size(), 3u * 3u * 12u);
  double volume = 0;
  for (double v : m.node_volume_m3) volume += v;
  // Straight, flat-faced cells between rings of 12: a prism over the annulus between two
  // regular 12-gons.
  const int n = 12;
  const double polygon = 0.5 * n * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(volume, polygon * ((kR + kT) * (kR + kT) - kR * kR) * kL, 1e-9 * volume);
  double mean = 0;
  for (double w : m.spring_weight) mean += w;
  EXPECT_NEAR(mean / m.spring_weight.size(), 1.0, 1e-12);  // No glue: every spring is a cell's.
  for (double w : m.spring_weight) EXPECT_GT(w, 0.0);
  // The drawn surfaces follow the lattice: every vertex's weights sum to 1.
  ASSERT_EQ(m.vertex_weights.size(), mesh.surface.positions.size());
  for (const auto& w : m.vertex_weights) EXPECT_NEAR(w[0] + w[1] + w[2] + w[3] + w[4] + w[5] + w[6] + w[7], 1.0, 1e-12);
}

TEST(Walls, CarriersInterpolateThePointWithinTheChordsSag) {
  Built b;
  const OrganMesh mesh = b.builder.finish();
  const auto& nodes = mesh.anatomy.myocardium.nodes;
  const double sag = (kR + kT) * (1 - std::cos(std::numbers::pi / 12));  // Arc to chord between two columns.
  for (const WallPoint& p : {WallPoint{0.1, 0.2, 0.3}, WallPoint{4.0, 0.75, 0.9}, WallPoint{2.0, 0.5, 0.0}}) {
    std::array<int, 8> carrier;
    std::array<double, 8> weight;
    b.wall.carriers(p, carrier, weight);
    Vec x = Vec::Zero();
    double total = 0;
    for (int k = 0; k < 8; ++k) {
      EXPECT_GE(weight[k], 0.0);
      total += weight[k];
      x += weight[k] * nodes[static_cast<std::size_t>(carrier[k])];
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
    EXPECT_LE((x - b.wall.point(p)).norm(), sag + 1e-12);
  }
}

TEST(Walls, NodesNearAreWithinReachNearestFirst) {
  Built b;  // Asked while building, before finish() hands the mesh over.
  const auto at = [&](int i) { return b.builder.node_position(i); };
  const Vec x = b.wall.point({0.3, 0.5, 1.0});
  const std::vector<int> near = b.wall.nodes_near(x, 0.01, 5, false);
  ASSERT_FALSE(near.empty());
  EXPECT_LE(near.size(), 5u);
  for (std::size_t i = 0; i < near.size(); ++i) {
    EXPECT_LE((at(near[i]) - x).norm(), 0.01);
    if (i > 0) {
      EXPECT_GE((at(near[i]) - x).norm(), (at(near[i - 1]) - x).norm());
    }
  }
  // On the outside only: every such node at the outside radius.
  for (int i : b.wall.nodes_near(x, 0.01, 100, true)) EXPECT_NEAR(from_axis(at(i)), kR + kT, 1e-12);
  const std::vector<int> outside = b.wall.outside_nodes();
  EXPECT_EQ(outside.size(), 3u * 12u);  // One layer of the three.
  for (int i : outside) EXPECT_NEAR(from_axis(at(i)), kR + kT, 1e-12);
}

TEST(Walls, TheDrawnSurfacesFaceOutOfTheWall) {
  Built b;
  const std::vector<Eigen::Vector3i> triangles = b.wall.triangles();
  const OrganMesh mesh = b.builder.finish();
  const auto& x = mesh.surface.positions;
  ASSERT_FALSE(triangles.empty());
  int lining = 0, outside = 0, ends = 0;
  for (const Eigen::Vector3i& t : triangles) {
    const Vec c = (x[t[0]] + x[t[1]] + x[t[2]]) / 3;
    const Vec n = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).normalized();
    const Vec radial = Vec(c.x(), c.y(), 0).normalized();
    if (std::abs(n.z()) > 0.9) {
      // The annuli joining lining and outside at the ends. Not checked here: they face
      // along the meridian direction of frame(), which points into the wall at both ends of
      // this tube (reported with issue 36).
      ++ends;
    } else if (from_axis(c) < kR + 0.5 * kT) {
      EXPECT_LT(n.dot(radial), 0.0);  // The lining faces into the lumen.
      ++lining;
    } else {
      EXPECT_GT(n.dot(radial), 0.0);  // The outside faces away from the axis.
      ++outside;
    }
  }
  EXPECT_GT(lining, 0);
  EXPECT_EQ(outside, lining);  // Both surfaces drawn alike.
  EXPECT_EQ(ends, 2 * 2 * 24);  // Two triangles a drawn column at each end.
  // The lining's triangles of every draw row are the lining's.
  EXPECT_EQ(static_cast<int>(b.wall.lining(0, b.wall.draw_rows() - 1).size()), lining);
}

}  // namespace
}  // namespace systole::mesh::procedural
