// The lattice model: its embedding reproduces the mesh at rest, carries the regions, pins
// and volume over, refines where a region asks for detail, and beats like the full model.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/reduced.h"
#include "sim/solvers/step.h"
#include "support/shapes.h"

namespace systole::sim {
namespace {

/// A ball whose upper half beats and whose bottom cap is pinned.
sim::OrganParams ball_organ(int lattice, int top_detail) {
  sim::OrganParams organ;
  organ.name = "ball";
  organ.body.mass_kg = 0.3;
  organ.body.stiffness_N_per_m = 200;
  organ.body.volume_stiffness_Pa = 3000;
  organ.body.lattice = lattice;
  sim::RegionParams top;
  top.name = "top";
  top.drive.waveform = sim::Waveform::kSine;
  top.drive.rate_hz = 1.0;
  top.drive.amplitude = 0.15;
  top.detail = top_detail;
  sim::RegionParams bottom;
  bottom.name = "bottom";
  bottom.pinned = true;
  organ.regions = {top, bottom};
  return organ;
}

mesh::OrganGeometry ball_geometry() {
  const auto surface = test::icosphere(0.05, 3);
  std::vector<int> region(surface.positions.size(), -1);
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (surface.positions[i].y() > 0.01) region[i] = 0;
    if (surface.positions[i].y() < -0.045) region[i] = 1;
  }
  return test::geometry_of(surface, region);
}

TEST(Reduced, EmbeddingReproducesTheMeshAtRest) {
  const auto geometry = ball_geometry();
  const ReducedBody body = build_reduced_model(ball_organ(6, 1), geometry, ModelOptions{});
  ASSERT_EQ(body.embedding.vertex_count(), static_cast<int>(geometry.mesh.surface.positions.size()));
  Eigen::Matrix3Xd embedded;
  embed(body.embedding, body.model.rest_positions, embedded);
  for (int v = 0; v < embedded.cols(); ++v) {
    EXPECT_NEAR(body.embedding.weight.col(v).sum(), 1.0, 1e-12);
    EXPECT_GE(body.embedding.weight.col(v).minCoeff(), -1e-12);
    EXPECT_LT((embedded.col(v) - geometry.mesh.surface.positions[v]).norm(), 1e-12);
  }
}

TEST(Reduced, KeepsMassRegionsPinsAndVolume) {
  const ReducedBody body = build_reduced_model(ball_organ(6, 1), ball_geometry(), ModelOptions{});
  const Model& m = body.model;
  EXPECT_LT(m.particle_count(), 400);  // The icosphere has 642 vertices.
  double free_mass = 0;
  for (int i = 0; i < m.particle_count(); ++i) free_mass += m.inverse_mass[i] > 0 ? 1.0 / m.inverse_mass[i] : 0.0;
  EXPECT_GT(free_mass, 0.2);  // Most of the 0.3 kg: only the pinned cap's share is held.
  EXPECT_LT(free_mass, 0.3);
  bool driven = false, pinned = false;
  for (int i = 0; i < m.particle_count(); ++i) {
    driven |= m.vertex_region[i] == 0;
    pinned |= m.inverse_mass[i] == 0;
    EXPECT_EQ(m.inverse_mass[i] == 0, m.vertex_region[i] == 1) << "particle " << i;
  }
  EXPECT_TRUE(driven);
  EXPECT_TRUE(pinned);
  ASSERT_TRUE(m.volume.enabled);
  EXPECT_GT(m.volume.rest_m3, 4.0 / 3.0 * M_PI * std::pow(0.05, 3));  // The hull encloses the surface.
}

TEST(Reduced, DetailRefinesOnlyItsRegion) {
  const auto geometry = ball_geometry();
  const ReducedBody coarse = build_reduced_model(ball_organ(5, 1), geometry, ModelOptions{});
  const ReducedBody fine = build_reduced_model(ball_organ(5, 2), geometry, ModelOptions{});
  const ReducedBody all_fine = build_reduced_model(ball_organ(10, 1), geometry, ModelOptions{});
  EXPECT_GT(fine.voxels, coarse.voxels);
  EXPECT_LT(fine.model.particle_count(), all_fine.model.particle_count() + coarse.model.particle_count());
  Eigen::Matrix3Xd embedded;
  embed(fine.embedding, fine.model.rest_positions, embedded);
  for (int v = 0; v < embedded.cols(); ++v) EXPECT_LT((embedded.col(v) - geometry.mesh.surface.positions[v]).norm(), 1e-12);
}

TEST(Reduced, BeatsLikeTheFullModel) {
  const auto geometry = ball_geometry();
  ModelOptions options;
  options.clip_s = 1;
  const Model full = build_model(ball_organ(0, 1), geometry, options);
  const ReducedBody reduced = build_reduced_model(ball_organ(8, 1), geometry, options);
  State a = initial_state(full), b = initial_state(reduced.model);
  for (int k = 0; k < 120; ++k) {  // Half a beat: the top at its most contracted.
    step(full, a, 1.0 / 240);
    step(reduced.model, b, 1.0 / 240);
  }
  ASSERT_FALSE(diagnose(reduced.model, b));
  Eigen::Matrix3Xd embedded;
  embed(reduced.embedding, b.x, embedded);
  double full_motion = 0, difference = 0;
  for (int v = 0; v < embedded.cols(); ++v) {
    full_motion += (a.x.col(v) - geometry.mesh.surface.positions[v]).norm();
    difference += (embedded.col(v) - a.x.col(v)).norm();
  }
  EXPECT_GT(full_motion, 0);
  EXPECT_LT(difference, 0.5 * full_motion);  // Same motion, to well within its size.
}

}  // namespace
}  // namespace systole::sim
