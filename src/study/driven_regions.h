#pragma once
// The periodically driven regions of a scene's render meshes, with what their beat is
// measured by: `systole bench` compares their beats with a reference's, `systole motion`
// compares each beat with the one before.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "world/world.h"

namespace systole::study {

/// A periodically driven region: its vertices in the organs' render positions stacked in
/// scene order, and its drive's rate (an organ with a volume drive counts as one such
/// region of every vertex). Ramped or irregular drives are not periodic and are left out.
struct DrivenRegion {
  std::string name;           ///< "heart.left_atrium"
  std::vector<int> vertices;  ///< Indices into the stacked render positions.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< The organ's rest centroid. unit: m
  double rate_hz = 0;
};

std::vector<DrivenRegion> driven_regions(const scene::Scene& scene, const world::World& world);

/// The region's signal: the mean distance of its vertices from its organ's rest centroid,
/// which contraction lowers and relaxation raises. unit: m
double radial_excursion_m(const DrivenRegion& region, const Eigen::Matrix3Xd& stacked_positions);

}  // namespace systole::study
