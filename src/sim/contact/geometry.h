#pragma once
// Point-triangle geometry for contact between closed surfaces: the closest point of a
// triangle, the feature it lies on, and the sign of the distance from the angle-weighted
// pseudo-normals of Bærentzen & Aanæs, "Signed distance computation using the angle
// weighted pseudonormal" (IEEE TVCG 11(3), 2005): for a closed, manifold, outward surface,
// the sign of (p - q) . N at the closest point q, N the pseudo-normal of q's feature (face,
// edge or vertex), is the sign of the distance. Stateless kernels, as
// sim/constraints/ are.

#include <Eigen/Core>
#include <vector>

namespace systole::sim::contact {

/// Where on a triangle a closest point lies: inside the face, on edge k (corners k, k+1),
/// or at corner k.
enum class Feature { kFace, kEdge, kCorner };

struct ClosestPoint {
  Eigen::Vector3d bary = Eigen::Vector3d::Zero();  ///< Weights of the three corners, summing to 1. unit: 1
  Feature feature = Feature::kFace;
  int index = 0;  ///< The edge or corner (0..2) for kEdge, kCorner.
};

/// The point of triangle (a, b, c) closest to p, after Ericson, "Real-Time Collision
/// Detection" (2005) §5.1.5: Voronoi regions of corners, then edges, then the face.
ClosestPoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c);

/// Per triangle, the triangle across each of its edges (edge k joins corners k and k+1);
/// -1 where an edge has no single neighbour (an open or non-manifold surface).
std::vector<Eigen::Vector3i> edge_neighbours(const std::vector<Eigen::Vector3i>& triangles, int vertex_count);

/// Unit face normals (outward for counter-clockwise triangles) and the vertices'
/// angle-weighted pseudo-normals (sum of incident face normals weighted by the corner
/// angle; Bærentzen & Aanæs eq. 2), unnormalized since only their sign against p - q counts.
void pseudo_normals(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles,
                    Eigen::Matrix3Xd& face_normal, Eigen::Matrix3Xd& vertex_normal);

/// The pseudo-normal of a closest point's feature on triangle t: the face's normal, the sum
/// of the two faces' normals across an edge, or the corner's angle-weighted normal.
Eigen::Vector3d feature_normal(const ClosestPoint& cp, int t, const std::vector<Eigen::Vector3i>& triangles,
                               const std::vector<Eigen::Vector3i>& neighbours, const Eigen::Matrix3Xd& face_normal,
                               const Eigen::Matrix3Xd& vertex_normal);

/// Generalized winding number of a closed surface about p (Jacobson, Kavan & Sorkine-Hornung,
/// "Robust inside-outside segmentation using generalized winding numbers", SIGGRAPH 2013):
/// the sum of the triangles' signed solid angles (Van Oosterom & Strackee 1983) over 4 pi;
/// 1 inside, 0 outside. O(triangles): for tests and reports, not the step. unit: 1
double winding_number(const Eigen::Vector3d& p, const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles);

}  // namespace systole::sim::contact
