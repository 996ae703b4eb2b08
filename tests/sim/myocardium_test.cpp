// The body of a generated anatomical heart (sim/myocardium.h): its particles are the
// myocardium's lattice nodes with the organ's mass, its springs carry the organ's stiffness
// on average, its drawn surface follows the lattice exactly at rest, and with blood its
// ventricles are closed chambers whose volume is the cavities' own.

#include "sim/myocardium.h"

#include <gtest/gtest.h>

#include <map>

#include "mesh/anatomy.h"
#include "mesh/inspect.h"
#include "mesh/procedural.h"
#include "sim/circulation.h"
#include "sim/reduced.h"

namespace systole::sim {
namespace {

const mesh::OrganGeometry& heart() {
  static const mesh::OrganGeometry g = [] {
    mesh::OrganGeometry geometry;
    geometry.mesh = mesh::generate_organ("anatomical_heart", 1);
    geometry.report = mesh::inspect(geometry.mesh.surface);
    geometry.vertex_region.assign(geometry.mesh.surface.positions.size(), -1);
    geometry.node_region.assign(geometry.mesh.anatomy.myocardium.nodes.size(), -1);
    return geometry;
  }();
  return g;
}

OrganParams organ(bool blood) {
  OrganParams o;
  o.name = "heart";
  o.body.mass_kg = 0.3;
  o.body.stiffness_N_per_m = 400;
  o.blood.enabled = blood;
  o.blood.aortic_Pa = 10000;
  o.blood.pulmonary_Pa = 2000;
  o.blood.filling_Pa = 800;
  o.blood.chordae = 0.5;
  return o;
}

ReducedBody body(bool blood) {
  ModelOptions options;
  options.dt_s = 1.0 / 60;
  options.clip_s = 1;
  return build_myocardium_model(organ(blood), heart(), options);
}

TEST(Myocardium, TheParticlesAreTheLatticeNodesWithTheOrgansMass) {
  const mesh::Myocardium& myo = heart().mesh.anatomy.myocardium;
  ASSERT_FALSE(myo.empty());
  const ReducedBody b = body(false);
  ASSERT_EQ(b.model.particle_count(), static_cast<int>(myo.nodes.size()));
  double mass = 0;
  for (int i = 0; i < b.model.particle_count(); ++i) {
    EXPECT_EQ(b.model.rest_positions.col(i), myo.nodes[i]);
    ASSERT_GT(b.model.inverse_mass[i], 0.0);
    mass += 1.0 / b.model.inverse_mass[i];
  }
  EXPECT_NEAR(mass, 0.3, 1e-12);
  EXPECT_FALSE(b.model.volume.enabled);  // The walls keep their own volume; the cavities may empty.
}

TEST(Myocardium, EachSpringGetsTheOrgansStiffnessTimesItsWeight) {
  const mesh::Myocardium& myo = heart().mesh.anatomy.myocardium;
  const ReducedBody b = body(false);
  ASSERT_EQ(b.model.springs.size(), static_cast<int>(myo.springs.size()));
  // The springs are stored by colour: find each lattice spring's weight by its ends.
  std::map<std::pair<int, int>, double> weight;
  for (std::size_t j = 0; j < myo.springs.size(); ++j) {
    const auto [a, c] = myo.springs[j];
    weight[{std::min(a, c), std::max(a, c)}] = myo.spring_weight[j];
  }
  for (int j = 0; j < b.model.springs.size(); ++j) {
    const int a = b.model.springs.a[j], c = b.model.springs.b[j];
    EXPECT_NEAR(b.model.springs.rest_m[j], (myo.nodes[a] - myo.nodes[c]).norm(), 1e-12);
    const auto w = weight.find({std::min(a, c), std::max(a, c)});
    ASSERT_NE(w, weight.end()) << a << "-" << c;
    EXPECT_NEAR(1.0 / b.model.springs.compliance_m_per_N[j], 400.0 * w->second, 1e-9 * 400 * w->second);
  }
}

TEST(Myocardium, TheDrawnSurfaceFollowsTheLatticeExactlyAtRest) {
  const ReducedBody b = body(false);
  const auto& surface = heart().mesh.surface.positions;
  ASSERT_EQ(b.embedding.vertex_count(), static_cast<int>(surface.size()));
  for (int v = 0; v < b.embedding.vertex_count(); ++v) EXPECT_NEAR(b.embedding.weight.col(v).sum(), 1.0, 1e-12);
  Eigen::Matrix3Xd drawn;
  embed(b.embedding, b.model.rest_positions, drawn);
  double worst = 0;
  for (std::size_t v = 0; v < surface.size(); ++v) worst = std::max(worst, (drawn.col(static_cast<Eigen::Index>(v)) - surface[v]).norm());
  EXPECT_LT(worst, 1e-12);
}

TEST(Myocardium, WithBloodEachVentricleIsAClosedChamberOfItsCavitysVolume) {
  const ReducedBody plain = body(false);
  EXPECT_FALSE(plain.model.circulation.enabled());
  const ReducedBody b = body(true);
  const Circulation& blood = b.model.circulation;
  ASSERT_EQ(blood.chambers.size(), 2u);
  EXPECT_EQ(blood.filling_Pa, 800);
  const mesh::Anatomy& anatomy = heart().mesh.anatomy;
  for (const Chamber& c : blood.chambers) {
    const mesh::Cavity* cavity = anatomy.cavity(c.name);
    ASSERT_NE(cavity, nullptr) << c.name;
    // Two computations of one volume: the chamber over the particles, the cavity's lining
    // closed by its rims over the drawn surface.
    const double cavity_m3 = mesh::cavity_volume(*cavity, heart().mesh.surface.positions);
    EXPECT_GT(cavity_m3, 1e-6) << c.name;  // More than a millilitre.
    EXPECT_NEAR(chamber_volume(c, b.model.rest_positions), cavity_m3, 1e-9 * cavity_m3) << c.name;
    EXPECT_NEAR(c.rest_m3, cavity_m3, 1e-9 * cavity_m3) << c.name;
    // Closed: moving the whole heart does not change the volume.
    Eigen::Matrix3Xd gradient;
    chamber_volume(c, b.model.rest_positions, gradient);
    EXPECT_LT(gradient.rowwise().sum().norm(), 1e-9 * gradient.cwiseAbs().sum()) << c.name;
    // The lining's rim is capped, and the cap belongs to a valve.
    EXPECT_TRUE(c.inflow_cap.first < c.inflow_cap.second || c.outflow_cap.first < c.outflow_cap.second) << c.name;
    const bool left = c.name == "left_ventricle";
    EXPECT_EQ(c.afterload_Pa, left ? 10000 : 2000);
    EXPECT_EQ(c.chordae_share, left ? 0.5 : 0.0);
    if (left) {
      EXPECT_FALSE(c.chordae_points.empty());
    }
  }
}

}  // namespace
}  // namespace systole::sim
