#pragma once
// Contact between organs: bodies whose closed surfaces must not pass through each other,
// resolved as unilateral position constraints after every coupled step, whatever solver
// stepped the bodies (docs/contact.md).
//
// Narrow phase: vertex-triangle proximity (Bridson, Fedkiw & Anderson, "Robust treatment of
// collisions, contact and friction for cloth animation", SIGGRAPH 2002): every surface vertex
// of one body against the nearest triangle of the other within a search radius, signed by
// the angle-weighted pseudo-normal (sim/contact/geometry.h), found through a sorted spatial
// hash (sim/contact/spatial_hash.h) on the surfaces where the step began (so the side a
// vertex came from decides its normal; the radius grows with the step's motion). Response: the non-penetration constraint
// C = n . (p - q) - thickness >= 0, projected with XPBD's zero-compliance update (Macklin,
// Müller & Chentanez, "XPBD: Position-Based Simulation of Compliant Constrained Dynamics",
// MIG 2016, eq. 18) in fixed order, then Coulomb friction on the step's relative tangential
// motion (Macklin et al., "Unified Particle Physics for Real-Time Applications", SIGGRAPH
// 2014, §6.1); the velocities are not given the corrections (a split impulse, so a deep
// correction is not a launch) but lose, per pushed contact, their approaching normal part
// and friction's share (inelastic: contact adds no energy). A surface vertex carried by particles
// through an Embedding (a lattice or a myocardium) moves them by its weights: particle k
// of a vertex with weights b moves by w_k b_k n dlambda, which moves the vertex by
// (sum b_k^2 w_k) n dlambda, its generalized inverse mass.
//
// Deterministic at any thread count: detection runs in parallel into one slot per vertex,
// gathered in vertex order; the projection runs in that order on one thread.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/contact/spatial_hash.h"
#include "sim/reduced.h"

namespace systole::sim::contact {

/// Two bodies that touch, and how.
struct PairParams {
  int body_a = 0, body_b = 1;   ///< Indices into the bodies given to resolve().
  double thickness_m = 0.002;   ///< The surfaces are kept at least this far apart. unit: m
  double friction = 0.1;        ///< Coulomb coefficient (static = kinetic). unit: 1
};

struct Params {
  std::vector<PairParams> pairs;
  int iterations = 4;  ///< Gauss-Seidel passes over the contacts per resolve.
  int threads = 1;     ///< Detection threads; the result is the same at any count.
};

/// One body as contact sees it: its closed, outward surface, whose vertices are its
/// particles or carried by them.
struct Body {
  std::string name;
  const std::vector<Eigen::Vector3i>* triangles = nullptr;  ///< Over the surface vertices.
  const Embedding* embedding = nullptr;    ///< Null or empty: surface vertex i is particle i.
  const Eigen::VectorXd* inverse_mass = nullptr;  ///< Per particle; 0 pinned. unit: 1/kg
  bool movable = true;                     ///< False: a static collider, never moved.
  Eigen::Matrix3Xd* x = nullptr;           ///< Particle positions. unit: m
  Eigen::Matrix3Xd* v = nullptr;           ///< Particle velocities. unit: m/s
};

/// One vertex within reach of another body's surface.
struct Contact {
  int vertex_body = 0, vertex = 0;  ///< The vertex (a surface vertex of vertex_body).
  int triangle_body = 0, triangle = 0;
  Eigen::Vector3d bary = Eigen::Vector3d::Zero();    ///< The closest point on the triangle. unit: 1
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< Out of the triangle's body, towards the vertex. unit: 1
  double thickness_m = 0;  ///< unit: m
  double friction = 0;     ///< unit: 1
  double lambda = 0;       ///< Accumulated normal multiplier of this resolve. unit: kg m
  double impulse = 0;      ///< Accumulated normal velocity impulse of this resolve. unit: kg m/s
};

/// What the last resolve found, and running totals since the workspace was made.
struct Stats {
  int contacts = 0;              ///< Vertices within reach in the last resolve.
  int active = 0;                ///< Of those, pushed apart (their constraint was violated).
  double deepest_m = 0;          ///< Deepest violation C < 0 found before projecting, last resolve. unit: m
  double worst_deepest_m = 0;    ///< The deepest over every resolve. unit: m
  double worst_remaining_m = 0;  ///< Worst violation left after projecting, over every resolve. unit: m
  long resolves = 0;
  long contacts_total = 0;       ///< Contacts summed over resolves.
};

/// What resolve keeps between calls (so stepping never allocates once warm): per body its
/// topology, surface positions at the step's start and now, normals and grid.
struct Workspace {
  struct PerBody {
    std::vector<Eigen::Vector3i> neighbours;  ///< edge_neighbours of its triangles.
    Eigen::Matrix3Xd start, now;              ///< Surface positions at the step's start, now. unit: m
    Eigen::Matrix3Xd face_normal, vertex_normal;
    Eigen::Matrix3Xd box_lower, box_upper;    ///< Per triangle, its bounding box at the step's start. unit: m
    Eigen::VectorXd vertex_inverse_mass;      ///< Generalized, per surface vertex. unit: 1/kg
    TriangleGrid grid;
    double grid_reach_m = 0;                  ///< The reach the grid was built with. unit: m
    Eigen::Matrix3Xd built_at;                ///< The surface the grid was built on. unit: m
    double mean_edge_m = 0;
  };
  std::vector<PerBody> bodies;
  std::vector<Contact> contacts;
  std::vector<Contact> slots;  ///< One per vertex during detection (triangle < 0: none).
  std::vector<char> pushed;    ///< Per body: moved by the last resolve (its solver must restart).
  Stats stats;
};

/// The surface position of vertex i: its particle, or its carriers' weighted sum. unit: m
Eigen::Vector3d surface_point(const Body& body, int i);

/// Every surface vertex's position into out. unit: m
void surface_positions(const Body& body, Eigen::Matrix3Xd& out);

/// Records the surfaces where the coupled step starts (friction measures the step's
/// tangential slip from there). Call before stepping the bodies.
void begin_step(const std::vector<Body>& bodies, Workspace& work);

/// Finds the contacts of every pair and projects them; the bodies' particles move and
/// their velocities take the corrections over dt_s. Throws Error(kInternal) on a body
/// without surface.
void resolve(const Params& params, std::vector<Body>& bodies, double dt_s, Workspace& work);

/// The deepest any surface vertex of one body of a pair lies inside the other's closed
/// surface (generalized winding number > 1/2, depth the distance to that surface; brute
/// force, for tests and reports): 0 when none is inside. `which`, when given, receives
/// "vertex i of 'a' in 'b'". unit: m
double deepest_inside_m(const std::vector<Body>& bodies, const PairParams& pair, std::string* which = nullptr);

}  // namespace systole::sim::contact
