#include "sim/contact/contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/error.h"
#include "sim/contact/geometry.h"

namespace systole::sim::contact {
namespace {

bool embedded(const Body& b) { return b.embedding != nullptr && !b.embedding->empty(); }

int surface_vertex_count(const Body& b) {
  return embedded(b) ? b.embedding->vertex_count() : static_cast<int>(b.x->cols());
}

/// Moves surface vertex i of b by w_eff * dlambda * direction through its particles (a
/// carrier k by w_k b_k dlambda direction; see contact.h).
void move_vertex(Body& b, Eigen::Matrix3Xd& field, int i, const Eigen::Vector3d& direction, double dlambda) {
  if (!b.movable) return;
  const Eigen::VectorXd& w = *b.inverse_mass;
  if (!embedded(b)) {
    field.col(i) += (w[i] * dlambda) * direction;
    return;
  }
  const Embedding& e = *b.embedding;
  for (int k = 0; k < 8; ++k) {
    const int node = e.node(k, i);
    field.col(node) += (w[node] * e.weight(k, i) * dlambda) * direction;
  }
}

/// A surface vertex's velocity: its particle's, or its carriers' weighted sum. unit: m/s
Eigen::Vector3d surface_velocity(const Body& body, int i) {
  if (!embedded(body)) return body.v->col(i);
  const Embedding& e = *body.embedding;
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (int k = 0; k < 8; ++k) u += e.weight(k, i) * body.v->col(e.node(k, i));
  return u;
}

/// Per surface vertex, the inverse mass it shows a constraint: sum of its carriers'
/// b_k^2 w_k (its particle's w when it is one); 0 on a static collider. unit: 1/kg
void generalized_inverse_masses(const Body& b, Eigen::VectorXd& out) {
  const int n = surface_vertex_count(b);
  out.setZero(n);
  if (!b.movable) return;
  const Eigen::VectorXd& w = *b.inverse_mass;
  if (!embedded(b)) {
    out = w;
    return;
  }
  const Embedding& e = *b.embedding;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 8; ++k) out[i] += e.weight(k, i) * e.weight(k, i) * w[e.node(k, i)];
  }
}

/// Sizes the workspace for these bodies (their topology and masses, once).
void prepare(const std::vector<Body>& bodies, Workspace& work) {
  if (work.bodies.size() == bodies.size()) return;
  work.bodies.assign(bodies.size(), {});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Body& body = bodies[b];
    if (body.triangles == nullptr || body.x == nullptr || body.v == nullptr || body.inverse_mass == nullptr) {
      throw Error(ExitCode::kInternal, "contact: body '" + body.name + "' has no surface or state");
    }
    Workspace::PerBody& pb = work.bodies[b];
    pb.neighbours = edge_neighbours(*body.triangles, surface_vertex_count(body));
    generalized_inverse_masses(body, pb.vertex_inverse_mass);
    surface_positions(body, pb.now);
    double sum = 0;
    for (const Eigen::Vector3i& t : *body.triangles) sum += (pb.now.col(t[1]) - pb.now.col(t[0])).norm();
    pb.mean_edge_m = body.triangles->empty() ? 0.01 : sum / static_cast<double>(body.triangles->size());
  }
}

/// Each triangle's bounding box. unit: m
void triangle_boxes(const Eigen::Matrix3Xd& y, const std::vector<Eigen::Vector3i>& triangles, Eigen::Matrix3Xd& lower,
                    Eigen::Matrix3Xd& upper) {
  const Eigen::Index n = static_cast<Eigen::Index>(triangles.size());
  lower.resize(3, n);
  upper.resize(3, n);
  for (Eigen::Index t = 0; t < n; ++t) {
    const Eigen::Vector3i& tri = triangles[t];
    lower.col(t) = y.col(tri[0]).cwiseMin(y.col(tri[1])).cwiseMin(y.col(tri[2]));
    upper.col(t) = y.col(tri[0]).cwiseMax(y.col(tri[1])).cwiseMax(y.col(tri[2]));
  }
}

/// How far each body's surface moved since the step began. unit: m
double largest_motion_m(const Workspace::PerBody& pb) {
  if (pb.start.cols() != pb.now.cols() || pb.now.cols() == 0) return 0;
  return (pb.now - pb.start).colwise().norm().maxCoeff();
}

/// The vertices of body a that were within `radius_m` of body b's surface where the step
/// began, into work.contacts in vertex order (the search runs on `threads` threads, one
/// result slot per vertex). The side and normal come from the step's start, when the
/// surfaces were apart: a vertex that crossed a thin body (the diaphragm) within the step is
/// still pushed back to the side it came from, never through (speculative contacts, as
/// Catto's, with the step's own motion as the margin).
// The triangle of body b nearest p within sqrt(r2) (its index, or -1), with the closest
// point on it and the squared distance; of equals, the lowest triangle.
int nearest_triangle(const Eigen::Vector3d& p, const Workspace::PerBody& pb, const std::vector<Eigen::Vector3i>& tris,
                     double r2, ClosestPoint& best_point, double& best) {
  const auto [first, last] = pb.grid.candidates(p);
  best = std::numeric_limits<double>::infinity();
  int best_triangle = -1;
  double limit = r2;
  for (const int* t = first; t != last; ++t) {
    // The triangle's box first: most candidates of a cell are farther than the reach or
    // than the best so far, and the box says so for a few comparisons.
    const Eigen::Vector3d outside =
        (pb.box_lower.col(*t) - p).cwiseMax(p - pb.box_upper.col(*t)).cwiseMax(0.0);
    if (outside.squaredNorm() > limit) continue;
    const Eigen::Vector3i& tri = tris[*t];
    const ClosestPoint cp = closest_on_triangle(p, pb.start.col(tri[0]), pb.start.col(tri[1]), pb.start.col(tri[2]));
    const Eigen::Vector3d q =
        cp.bary[0] * pb.start.col(tri[0]) + cp.bary[1] * pb.start.col(tri[1]) + cp.bary[2] * pb.start.col(tri[2]);
    const double d2 = (p - q).squaredNorm();
    if (d2 < best) {  // Strict: of equals, the lowest triangle (candidates ascend).
      best = d2;
      limit = std::min(limit, d2);
      best_point = cp;
      best_triangle = *t;
    }
  }
  return best_triangle;
}

void detect(const std::vector<Body>& bodies, const PairParams& pair, int a, int b, double radius_m, int threads,
            Workspace& work) {
  const Workspace::PerBody& pa = work.bodies[a];
  const Workspace::PerBody& pb = work.bodies[b];
  const std::vector<Eigen::Vector3i>& tris = *bodies[b].triangles;
  const int n = static_cast<int>(pa.start.cols());
  work.slots.resize(n);
  const double r2 = radius_m * radius_m;
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1 && n > 256)
  for (int i = 0; i < n; ++i) {
    Contact& slot = work.slots[i];
    slot.triangle = -1;
    const Eigen::Vector3d p = pa.start.col(i);
    if (!pb.grid.near(p)) continue;
    double best = 0;
    ClosestPoint best_point;
    const int best_triangle = nearest_triangle(p, pb, tris, r2, best_point, best);
    if (best_triangle < 0 || best > r2) continue;
    const Eigen::Vector3i& tri = tris[best_triangle];
    if (pa.vertex_inverse_mass[i] == 0 && pb.vertex_inverse_mass[tri[0]] == 0 && pb.vertex_inverse_mass[tri[1]] == 0 &&
        pb.vertex_inverse_mass[tri[2]] == 0) {
      continue;  // Neither side can move.
    }
    const Eigen::Vector3d q = best_point.bary[0] * pb.start.col(tri[0]) + best_point.bary[1] * pb.start.col(tri[1]) +
                              best_point.bary[2] * pb.start.col(tri[2]);
    const Eigen::Vector3d pseudo = feature_normal(best_point, best_triangle, tris, pb.neighbours, pb.face_normal, pb.vertex_normal);
    const Eigen::Vector3d diff = p - q;
    const double dist = diff.norm();
    const double sign = diff.dot(pseudo) < 0 ? -1.0 : 1.0;
    Eigen::Vector3d normal = dist > 1e-9 * radius_m ? Eigen::Vector3d(sign * diff / dist) : pseudo.normalized();
    if (!normal.allFinite()) continue;  // A degenerate patch: no direction to push along.
    slot.vertex_body = a;
    slot.vertex = i;
    slot.triangle_body = b;
    slot.triangle = best_triangle;
    slot.bary = best_point.bary;
    slot.normal = normal;
    slot.thickness_m = pair.thickness_m;
    slot.friction = pair.friction;
    slot.lambda = 0;
    slot.impulse = 0;
  }
  for (int i = 0; i < n; ++i)
    if (work.slots[i].triangle >= 0) work.contacts.push_back(work.slots[i]);
}

/// The constraint C = n . (p - q) - thickness of a contact now, and its generalized
/// inverse mass W = w_p + sum bary_k^2 w_k.
double constraint_now(const std::vector<Body>& bodies, const Workspace& work, const Contact& c, double& w_total) {
  const Body& vb = bodies[c.vertex_body];
  const Body& tb = bodies[c.triangle_body];
  const Eigen::Vector3i& tri = (*tb.triangles)[c.triangle];
  const Eigen::Vector3d p = surface_point(vb, c.vertex);
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  const Eigen::VectorXd& wt = work.bodies[c.triangle_body].vertex_inverse_mass;
  w_total = work.bodies[c.vertex_body].vertex_inverse_mass[c.vertex];
  for (int k = 0; k < 3; ++k) {
    q += c.bary[k] * surface_point(tb, tri[k]);
    w_total += c.bary[k] * c.bary[k] * wt[tri[k]];
  }
  return c.normal.dot(p - q) - c.thickness_m;
}

/// Moves a contact's vertex by w_p dlambda direction and its triangle's corners by
/// -bary_k w_k dlambda direction.
void apply(std::vector<Body>& bodies, const Contact& c, const Eigen::Vector3d& direction, double dlambda,
           Eigen::Matrix3Xd* Body::*field = &Body::x) {
  Body& vb = bodies[c.vertex_body];
  Body& tb = bodies[c.triangle_body];
  const Eigen::Vector3i& tri = (*tb.triangles)[c.triangle];
  move_vertex(vb, *(vb.*field), c.vertex, direction, dlambda);
  for (int k = 0; k < 3; ++k) move_vertex(tb, *(tb.*field), tri[k], direction, -c.bary[k] * dlambda);
}

/// The contact's relative velocity, vertex minus the triangle's point. unit: m/s
Eigen::Vector3d relative_velocity(const std::vector<Body>& bodies, const Contact& c) {
  const Body& tb = bodies[c.triangle_body];
  const Eigen::Vector3i& tri = (*tb.triangles)[c.triangle];
  Eigen::Vector3d u = surface_velocity(bodies[c.vertex_body], c.vertex);
  for (int k = 0; k < 3; ++k) u -= c.bary[k] * surface_velocity(tb, tri[k]);
  return u;
}

/// The velocity half of the split impulse (Bridson et al. 2002 §7.2; Catto's split impulse):
/// the projection moved the surfaces apart without touching the velocities (so a deep
/// correction never becomes a launch), and here each pushed contact loses its approaching
/// normal velocity (an inelastic impulse, accumulated >= 0), then Coulomb friction bounded
/// by friction x the contact's whole normal impulse (the push over the step plus this one).
void contact_velocities(const Params& params, std::vector<Body>& bodies, double dt_s, Workspace& work) {
  for (int iteration = 0; iteration < params.iterations; ++iteration) {
    for (Contact& c : work.contacts) {
      if (c.lambda <= 0) continue;
      double w_total = 0;
      constraint_now(bodies, work, c, w_total);
      if (w_total <= 0) continue;
      const double approach = c.normal.dot(relative_velocity(bodies, c));
      const double dj = std::max(-approach / w_total, -c.impulse);
      if (dj == 0) continue;
      c.impulse += dj;
      apply(bodies, c, c.normal, dj, &Body::v);
    }
  }
  for (const Contact& c : work.contacts) {
    if (c.lambda <= 0 || c.friction <= 0) continue;
    double w_total = 0;
    constraint_now(bodies, work, c, w_total);
    const Eigen::Vector3d u = relative_velocity(bodies, c);
    const Eigen::Vector3d tangential = u - c.normal.dot(u) * c.normal;
    const double speed = tangential.norm();
    if (speed < 1e-15 || w_total <= 0) continue;
    const double removed = std::min(speed, c.friction * (c.impulse + c.lambda / dt_s) * w_total);
    apply(bodies, c, tangential / speed, -removed / w_total, &Body::v);
  }
}

/// Gauss-Seidel over the contacts: dlambda = -C / W (XPBD, zero compliance), the total
/// kept >= 0 so a contact only ever pushes (a pass may give back what an earlier one
/// over-pushed, never pull the surfaces together).
void project_normals(const Params& params, std::vector<Body>& bodies, Workspace& work) {
  double deepest = 0;
  for (int iteration = 0; iteration < params.iterations; ++iteration) {
    for (Contact& c : work.contacts) {
      double w_total = 0;
      const double violation = constraint_now(bodies, work, c, w_total);
      if (iteration == 0) deepest = std::min(deepest, violation);
      if (w_total <= 0 || (violation >= 0 && c.lambda == 0)) continue;
      const double dlambda = std::max(-violation / w_total, -c.lambda);
      c.lambda += dlambda;
      apply(bodies, c, c.normal, dlambda);
    }
  }
  work.stats.deepest_m = -deepest;
}

/// Coulomb friction on the step's relative tangential slip (Macklin et al. 2014, eq. 24):
/// removed entirely while it is below friction x the normal correction (sticking), else by
/// that much (sliding).
void apply_friction(std::vector<Body>& bodies, Workspace& work) {
  for (const Contact& c : work.contacts) {
    if (c.lambda <= 0 || c.friction <= 0) continue;
    const Body& vb = bodies[c.vertex_body];
    const Body& tb = bodies[c.triangle_body];
    const Eigen::Vector3i& tri = (*tb.triangles)[c.triangle];
    const Workspace::PerBody& pv = work.bodies[c.vertex_body];
    const Workspace::PerBody& pt = work.bodies[c.triangle_body];
    Eigen::Vector3d slip = surface_point(vb, c.vertex) - pv.start.col(c.vertex);
    for (int k = 0; k < 3; ++k) slip -= c.bary[k] * (surface_point(tb, tri[k]) - pt.start.col(tri[k]));
    const Eigen::Vector3d tangential = slip - c.normal.dot(slip) * c.normal;
    const double length = tangential.norm();
    if (length < 1e-15) continue;
    double w_total = pv.vertex_inverse_mass[c.vertex];
    for (int k = 0; k < 3; ++k) w_total += c.bary[k] * c.bary[k] * pt.vertex_inverse_mass[tri[k]];
    const double removed = std::min(length, c.friction * c.lambda * w_total);
    apply(bodies, c, tangential / length, -removed / w_total);
  }
}

}  // namespace

Eigen::Vector3d surface_point(const Body& body, int i) {
  if (!embedded(body)) return body.x->col(i);
  const Embedding& e = *body.embedding;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 8; ++k) p += e.weight(k, i) * body.x->col(e.node(k, i));
  return e.offset.cols() ? Eigen::Vector3d(p + e.offset.col(i)) : p;
}

void surface_positions(const Body& body, Eigen::Matrix3Xd& out) {
  if (!embedded(body)) {
    out = *body.x;
    return;
  }
  embed(*body.embedding, *body.x, out);
}

void begin_step(const std::vector<Body>& bodies, Workspace& work) {
  prepare(bodies, work);
  for (std::size_t b = 0; b < bodies.size(); ++b) surface_positions(bodies[b], work.bodies[b].start);
}

namespace {

// Normals and boxes now; the grid only when the surface has moved more since it was
// built than its spare reach covers (fat boxes: a triangle that moved m since is within
// reach of p now only if it was within reach + m then). A static collider's is built once.
void refresh_grids(const std::vector<Body>& bodies, const std::vector<double>& reach, Workspace& work) {
  const int count = static_cast<int>(bodies.size());
  for (int b = 0; b < count; ++b) {
    if (reach[b] == 0) continue;
    Workspace::PerBody& pb = work.bodies[b];
    if (bodies[b].movable || pb.face_normal.cols() == 0) {
      pseudo_normals(pb.start, *bodies[b].triangles, pb.face_normal, pb.vertex_normal);
      triangle_boxes(pb.start, *bodies[b].triangles, pb.box_lower, pb.box_upper);
    }
    const double moved = pb.start.cols() > 0 && pb.built_at.cols() == pb.start.cols() ? (pb.start - pb.built_at).colwise().norm().maxCoeff()
                                                                : std::numeric_limits<double>::infinity();
    if (reach[b] + moved <= pb.grid_reach_m) continue;
    const double built_reach = reach[b] + std::max(reach[b], pb.mean_edge_m);
    // Cells 1.5 times the reach or the mean edge: a triangle lands in a few cells, a cell
    // holds a few triangles.
    pb.grid.build(pb.start, *bodies[b].triangles, 1.5 * std::max(built_reach, pb.mean_edge_m), built_reach);
    pb.grid_reach_m = built_reach;
    pb.built_at = pb.start;
  }
}

}  // namespace

void resolve(const Params& params, std::vector<Body>& bodies, double dt_s, Workspace& work) {
  prepare(bodies, work);
  const int count = static_cast<int>(bodies.size());
  std::vector<double> motion(count, 0.0), reach(count, 0.0);
  for (int b = 0; b < count; ++b) {
    Workspace::PerBody& pb = work.bodies[b];
    surface_positions(bodies[b], pb.now);
    if (pb.start.cols() != pb.now.cols()) pb.start = pb.now;  // No begin_step: no slip, no motion.
    motion[b] = largest_motion_m(pb);
  }
  // A vertex that was thickness clear of a surface when the step began is now within
  // thickness + both bodies' motion of it, on either side: search twice the thickness plus
  // the motion, so no vertex that crossed in this step is missed.
  auto radius = [&](const PairParams& p) { return 2.0 * p.thickness_m + motion[p.body_a] + motion[p.body_b]; };
  for (const PairParams& p : params.pairs) {
    reach[p.body_a] = std::max(reach[p.body_a], radius(p));
    reach[p.body_b] = std::max(reach[p.body_b], radius(p));
  }
  refresh_grids(bodies, reach, work);
  work.contacts.clear();
  for (const PairParams& p : params.pairs) {
    detect(bodies, p, p.body_a, p.body_b, radius(p), params.threads, work);
    detect(bodies, p, p.body_b, p.body_a, radius(p), params.threads, work);
  }
  project_normals(params, bodies, work);
  apply_friction(bodies, work);
  Stats& s = work.stats;
  s.contacts = static_cast<int>(work.contacts.size());
  s.active = 0;
  double remaining = 0;
  for (const Contact& c : work.contacts) {
    double w_total = 0;
    remaining = std::max(remaining, -constraint_now(bodies, work, c, w_total));
    if (c.lambda > 0) ++s.active;
  }
  s.worst_deepest_m = std::max(s.worst_deepest_m, s.deepest_m);
  s.worst_remaining_m = std::max(s.worst_remaining_m, remaining);
  ++s.resolves;
  s.contacts_total += s.contacts;
  contact_velocities(params, bodies, dt_s, work);
  work.pushed.assign(count, 0);
  for (const Contact& c : work.contacts) {
    if (c.lambda == 0) continue;
    work.pushed[c.vertex_body] = work.pushed[c.triangle_body] = 1;
  }
}

double deepest_inside_m(const std::vector<Body>& bodies, const PairParams& pair, std::string* which) {
  double deepest = 0;
  for (int side = 0; side < 2; ++side) {
    const Body& vb = bodies[side == 0 ? pair.body_a : pair.body_b];
    const Body& tb = bodies[side == 0 ? pair.body_b : pair.body_a];
    Eigen::Matrix3Xd pv, pt;
    surface_positions(vb, pv);
    surface_positions(tb, pt);
    const Eigen::Vector3d lo = pt.rowwise().minCoeff(), hi = pt.rowwise().maxCoeff();
    for (Eigen::Index i = 0; i < pv.cols(); ++i) {
      const Eigen::Vector3d p = pv.col(i);
      if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
      if (winding_number(p, pt, *tb.triangles) <= 0.5) continue;
      double d2 = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3i& t : *tb.triangles) {
        const ClosestPoint cp = closest_on_triangle(p, pt.col(t[0]), pt.col(t[1]), pt.col(t[2]));
        const Eigen::Vector3d q = cp.bary[0] * pt.col(t[0]) + cp.bary[1] * pt.col(t[1]) + cp.bary[2] * pt.col(t[2]);
        d2 = std::min(d2, (p - q).squaredNorm());
      }
      if (std::sqrt(d2) > deepest) {
        deepest = std::sqrt(d2);
        if (which) {
          std::ostringstream m;
          m << "vertex " << i << " of '" << vb.name << "' in '" << tb.name << "'";
          *which = m.str();
        }
      }
    }
  }
  return deepest;
}

}  // namespace systole::sim::contact
