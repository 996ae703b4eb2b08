#pragma once
// Whether points lie inside closed surfaces: the winding number of outward-facing closed
// triangle surfaces about each point (1 inside one of them, 0 outside all, 2 where two
// overlap), counted as the signed crossings of a ray from the point: a surface crossed
// on its way out counts +1, on its way in -1. For closed surfaces this is the winding number
// exactly (Jacobson, Kavan & Sorkine-Hornung 2013, "Robust inside-outside segmentation using
// generalized winding numbers", ACM TOG 32:33, sec. 3), and it costs a few triangles per point
// instead of every triangle's solid angle.
//
// The ray runs in one fixed direction, oblique to the axes; its crossings are found in the
// plane across it, where a point on an edge shared by two triangles is counted once by the
// rasterizer's top-left rule (each edge's side computed once, from its lower-numbered end),
// so a ray through an edge or a corner is neither lost nor counted twice.

#include <Eigen/Core>
#include <vector>

namespace systole::mesh {

/// The direction of the rays the crossings are counted along (for tests that aim one at an
/// edge or a corner). unit: 1
const Eigen::Vector3d& winding_ray();

/// The winding number about each column of `points` of the closed surfaces `triangles`
/// over `positions` (each triangle counter-clockwise seen from outside). A point on the
/// surface itself gets either side's number. unit: 1
std::vector<int> winding_numbers(const Eigen::Matrix3Xd& positions, const std::vector<Eigen::Vector3i>& triangles,
                                 const Eigen::Matrix3Xd& points);

}  // namespace systole::mesh
