#pragma once
// Reduced models (Kenwright & Sinmai §4): fewer particles carry the motion. The organ's
// surface is covered by a shell of voxels; the voxel corners are the particles, joined by
// springs along the voxel edges and diagonals; the render mesh follows by trilinear
// embedding. A region's `detail` splits its voxels (2 or 4 per axis) so a region that
// matters keeps detail while the rest stays coarse. Regions, drives, volume and
// interactions act on the lattice exactly as on the full model.

#include <Eigen/Core>
#include <vector>

#include "mesh/geometry.h"
#include "sim/model.h"
#include "sim/params.h"

namespace systole::sim {

/// Render-mesh vertices as fixed combinations of particles: vertex v = sum over k of
/// weight(k, v) * x(node(k, v)) (+ offset(v)). Empty: the render mesh is the particles themselves.
struct Embedding {
  Eigen::Matrix<int, 8, Eigen::Dynamic> node;       ///< The 8 corners of the voxel holding each vertex.
  Eigen::Matrix<double, 8, Eigen::Dynamic> weight;  ///< Trilinear weights, summing to 1. unit: 1
  /// Per vertex, added: where it lies at rest beyond the weighted particles (a myocardium's
  /// smooth surface over its coarser lattice); empty: none. unit: m
  Eigen::Matrix3Xd offset;

  bool empty() const { return node.cols() == 0; }
  int vertex_count() const { return static_cast<int>(node.cols()); }
};

/// A lattice body and how its render mesh follows it.
struct ReducedBody {
  Model model;
  Embedding embedding;
  int voxels = 0;  ///< Voxels in the lattice (after refinement).
};

/// Builds the lattice model of `organ` (organ.body.lattice > 0): voxel edge = longest
/// side of the bounding box / organ.body.lattice, split by each region's `detail`.
/// Stiffness: every lattice spring gets c * body.stiffness, with c chosen so the lattice
/// stores the surface network's energy under the in-plane stretch that the drive and the
/// volume produce (sum k L^2 (1 - (n.d)^2)^2 over lattice springs = sum k L^2 over surface
/// edges, n the surface normal, d the spring direction). Volume: the lattice hull
/// (outer faces of the filled voxels) with bulk modulus and volume drive rescaled by the
/// hull's area and volume so that the same surface motion meets the same pressure.
ReducedBody build_reduced_model(const OrganParams& organ, const mesh::OrganGeometry& geometry,
                                const ModelOptions& options);

/// The render-mesh positions of particles x: out = x when the embedding is empty. unit: m
void embed(const Embedding& embedding, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out);

/// One render vertex's position, as embed() places it. unit: m
Eigen::Vector3d embed_vertex(const Embedding& embedding, const Eigen::Matrix3Xd& x, int vertex);

}  // namespace systole::sim
