#include "sim/model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "common/error.h"
#include "sim/drive.h"
#include "sim/graph_coloring.h"
#include "sim/solvers/step_size.h"

namespace systole::sim {
namespace {

/// Unique undirected edges of a triangle surface, in a deterministic order.
std::vector<std::pair<int, int>> unique_edges(const std::vector<Eigen::Vector3i>& triangles) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(triangles.size() * 3);
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/// For each edge shared by exactly two triangles, the two corners opposite it: a spring
/// between them resists folding about the edge (a cheap bending model that works the same
/// in every solver, unlike dihedral-angle constraints).
std::vector<std::pair<int, int>> opposite_corners(const std::vector<Eigen::Vector3i>& triangles) {
  std::map<std::pair<int, int>, std::vector<int>> across;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      across[{std::min(i, j), std::max(i, j)}].push_back(t[(k + 2) % 3]);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [edge, corners] : across) {
    if (corners.size() != 2 || corners[0] == corners[1]) continue;  // Boundary or non-manifold: no hinge.
    pairs.emplace_back(std::min(corners[0], corners[1]), std::max(corners[0], corners[1]));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

/// The particles within `radius` of `centre`, in index order.
std::vector<int> particles_near(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& centre, double radius) {
  std::vector<int> found;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if ((x.col(i) - centre).norm() <= radius) found.push_back(static_cast<int>(i));
  }
  return found;
}

void add_interactions(Model& m, const std::vector<InteractionParams>& interactions, double reach_m) {
  for (const auto& in : interactions) {
    std::vector<int> patch = particles_near(m.rest_positions, in.at_m, in.radius_m + reach_m);
    if (patch.empty()) {
      throw Error(ExitCode::kDataError,
                  in.where + ": " + in.key + ".at: no vertex of '" + m.name + "' lies within " + in.key + ".radius (" +
                      std::to_string(in.radius_m) + " m) of it; move `at` onto the organ's surface (where its transform "
                      "puts it) or raise `radius`");
    }
    if (in.kind == InteractionKind::kPoke) {
      Poke p;
      p.force_per_particle_N = in.force_N / double(patch.size());
      p.particles = std::move(patch);
      p.start_s = in.start_s;
      p.end_s = in.start_s + in.duration_s;
      p.drive = in.drive;
      m.pokes.push_back(std::move(p));
    } else {
      Grab g;
      for (int i : patch) g.offsets_m.push_back(m.rest_positions.col(i) - in.path.front().position_m);
      g.particles = std::move(patch);
      g.path = in.path;
      g.compliance_m_per_N = 1.0 / in.stiffness_N_per_m;
      m.grabs.push_back(std::move(g));
    }
  }
}

/// Tethered regions as grabs that never let go: each free particle of the region held by a
/// zero-length spring of stiffness / particles to its rest place + offset. Every solver
/// already integrates grabs (XPBD's attachments, the explicit and implicit forces, the
/// projective matrix), so a tether is one of them with a handle that stays put.
void add_tethers(Model& m) {
  for (std::size_t r = 0; r < m.regions.size(); ++r) {
    const RegionParams& region = m.regions[r];
    if (region.tether_stiffness_N_per_m <= 0) continue;
    Grab g;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int i = 0; i < m.particle_count(); ++i) {
      if (m.vertex_region.empty() || m.vertex_region[i] != static_cast<int>(r) || m.inverse_mass[i] == 0) continue;
      g.particles.push_back(i);
      centre += m.rest_positions.col(i);
    }
    if (g.particles.empty()) {
      throw Error(ExitCode::kDataError, "organ '" + m.name + "': region '" + region.name +
                                            "' has a tether but no free particle to hold");
    }
    centre /= static_cast<double>(g.particles.size());
    for (int i : g.particles) g.offsets_m.push_back(m.rest_positions.col(i) - centre);
    const Eigen::Vector3d anchor = centre + region.tether_offset_m;
    // Held from the start to long after any clip (grab_active spans the keys).
    g.path = {{0.0, anchor}, {1e12, anchor}};
    g.compliance_m_per_N = static_cast<double>(g.particles.size()) / region.tether_stiffness_N_per_m;
    m.grabs.push_back(std::move(g));
  }
}

}  // namespace

Eigen::VectorXd lumped_masses(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles,
                              double total_mass_kg) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(x.cols());
  double total_area = 0;
  for (const auto& t : triangles) {
    const double a = 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
    for (int k = 0; k < 3; ++k) area[t[k]] += a / 3.0;
    total_area += a;
  }
  Eigen::VectorXd mass(x.cols());
  // A vertex in no triangle (or only degenerate ones) still needs a finite mass.
  const double floor_kg = total_mass_kg / double(std::max<Eigen::Index>(1, x.cols())) * 1e-3;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    mass[i] = std::max(floor_kg, total_area > 0 ? total_mass_kg * area[i] / total_area : 0.0);
  }
  return mass;
}

BodyParts surface_body(const OrganParams& organ, const mesh::OrganGeometry& geometry) {
  const auto& surface = geometry.mesh.surface;
  BodyParts parts;
  const int n = static_cast<int>(surface.positions.size());
  parts.rest_positions.resize(3, n);
  for (int i = 0; i < n; ++i) parts.rest_positions.col(i) = surface.positions[i];
  parts.mass_kg = lumped_masses(parts.rest_positions, surface.triangles, organ.body.mass_kg);
  parts.particle_region = geometry.vertex_region;
  // Springs on every surface edge, then (when asked for) bending springs across every
  // interior edge.
  parts.springs = unique_edges(surface.triangles);
  parts.stretch_count = static_cast<int>(parts.springs.size());
  parts.spring_stiffness_N_per_m.assign(parts.springs.size(), organ.body.stiffness_N_per_m);
  if (organ.body.bending_N_per_m > 0) {
    for (const auto& pair : opposite_corners(surface.triangles)) {
      parts.springs.push_back(pair);
      parts.spring_stiffness_N_per_m.push_back(organ.body.bending_N_per_m);
    }
  }
  // "Enclosed volume" means nothing on an open surface.
  if (geometry.report.encloses_volume()) parts.volume_triangles = surface.triangles;
  return parts;
}

Model build_model(const OrganParams& organ, const mesh::OrganGeometry& geometry, const ModelOptions& options) {
  return build_model(organ, surface_body(organ, geometry), options);
}

namespace {

// A particle's region, or -1 on a body without regions.
int region_of(const Model& m, int v) { return m.vertex_region.empty() ? -1 : m.vertex_region[v]; }

// The solver's settings, the regions and each driven region's irregular beats, drawn in
// region order so each region keeps its own stream.
void set_regions(Model& m, const OrganParams& organ, const ModelOptions& options) {
  m.name = organ.name;
  m.method = options.solver.method;
  m.substeps = options.solver.substeps;
  m.iterations = options.solver.iterations;
  m.threads = options.solver.threads;
  m.gravity = options.gravity;
  m.drag_per_s = organ.body.drag_per_s;
  m.ramp_s = options.clip_s;
  m.floor = options.floor;
  m.regions = organ.regions;
  for (std::size_t r = 0; r < m.regions.size(); ++r) {
    const auto& d = m.regions[r].drive;
    std::vector<double> beats;
    if (d.irregularity > 0 && d.waveform != Waveform::kNone) {
      beats = irregular_beats(d.irregularity, options.seed, r, drive_cycles(d, options.clip_s, options.clip_s));
    }
    m.beat_boundaries.push_back(std::move(beats));
  }
}

// Rest positions and inverse masses, pinned regions held (zero inverse mass) and moved
// regions listed as kinematic.
void set_particles(Model& m, BodyParts& parts) {
  m.vertex_region = std::move(parts.particle_region);
  const int n = static_cast<int>(parts.rest_positions.cols());
  m.rest_positions = std::move(parts.rest_positions);
  if (n > 0) {
    m.rest_extent_m = (m.rest_positions.rowwise().maxCoeff() - m.rest_positions.rowwise().minCoeff()).norm();
  }

  m.inverse_mass = parts.mass_kg.cwiseInverse();
  for (int i = 0; i < n; ++i) {
    const int r = region_of(m, i);
    if (r >= 0 && m.regions[r].pinned) m.inverse_mass[i] = 0;
  }
  for (std::size_t r = 0; r < m.regions.size(); ++r) {
    if (m.regions[r].motion.empty()) continue;
    KinematicRegion k;
    k.motion = m.regions[r].motion;
    for (int i = 0; i < n; ++i)
      if (region_of(m, i) == static_cast<int>(r)) k.particles.push_back(i);
    m.kinematic.push_back(std::move(k));
  }
}

// The springs, stored by colour so springs of one colour share no particle, each with
// its region's blended stiffness and damping. A spring between two pinned particles does
// nothing and is not built.
void build_springs(Model& m, const OrganParams& organ, const BodyParts& parts) {
  const int n = static_cast<int>(m.rest_positions.cols());
  std::vector<int> a, b, kept;
  std::vector<double> stiffness;
  for (std::size_t p = 0; p < parts.springs.size(); ++p) {
    const auto [i, j] = parts.springs[p];
    if (m.inverse_mass[i] == 0 && m.inverse_mass[j] == 0) continue;
    kept.push_back(static_cast<int>(p));
    a.push_back(i);
    b.push_back(j);
    stiffness.push_back(parts.spring_stiffness_N_per_m[p]);
    ++(static_cast<int>(p) < parts.stretch_count ? m.springs.stretch_count : m.springs.bending_count);
  }
  const std::vector<int> color = color_pairs(a, b, n);
  const int colors = a.empty() ? 0 : *std::max_element(color.begin(), color.end()) + 1;
  std::vector<int> order(a.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) { return color[p] < color[q]; });

  Springs& s = m.springs;
  s.color_begin.assign(colors + 1, 0);
  for (int c : color) ++s.color_begin[c + 1];
  std::partial_sum(s.color_begin.begin(), s.color_begin.end(), s.color_begin.begin());
  for (int idx : order) {
    const int i = a[idx], j = b[idx];
    const int ri = region_of(m, i), rj = region_of(m, j);
    const double stiffness_scale = boundary_blend(m.regions, ri, rj, &RegionParams::stiffness_scale);
    const double damping_scale = boundary_blend(m.regions, ri, rj, &RegionParams::damping_scale);
    s.a.push_back(i);
    s.b.push_back(j);
    s.rest_m.push_back((m.rest_positions.col(i) - m.rest_positions.col(j)).norm());
    s.compliance_m_per_N.push_back(1.0 / (stiffness[idx] * stiffness_scale));
    s.damping_s.push_back(organ.body.damping_s * damping_scale);
    s.region_a.push_back(ri);
    s.region_b.push_back(rj);
    if (!parts.fibre_share.empty()) {
      s.fibre_share.push_back(parts.fibre_share[kept[idx]]);
      s.normal_share.push_back(parts.normal_share[kept[idx]]);
      s.cross_fibre.push_back(parts.cross_fibre[kept[idx]]);
    }
  }
  if (!parts.fibre_share.empty()) s.fibre_tension = organ.body.fibre_tension;
}

// The volume constraint needs a closed surface; a volume drive without one is an error.
void build_volume(Model& m, const OrganParams& organ, BodyParts& parts, const ModelOptions& options) {
  if (organ.body.volume_stiffness_Pa > 0 && !parts.volume_triangles.empty()) {
    m.volume.enabled = true;
    m.volume.triangles = std::move(parts.volume_triangles);
    m.volume.rest_m3 = enclosed_volume(m.rest_positions, m.volume.triangles);
    m.volume.compliance_m5_per_N = m.volume.rest_m3 / (organ.body.volume_stiffness_Pa * parts.volume_stiffness_scale);
    m.volume.drive = organ.body.volume_drive;
    m.volume.drive.amplitude *= parts.volume_drive_scale;
    const Drive& d = m.volume.drive;
    if (d.irregularity > 0 && d.waveform != Waveform::kNone) {
      // Its own stream after the regions', so adding it changes no region's beats.
      m.volume.beat_boundaries = irregular_beats(d.irregularity, options.seed, m.regions.size(),
                                                 drive_cycles(d, options.clip_s, options.clip_s));
    }
  } else if (organ.body.volume_drive.waveform != Waveform::kNone) {
    throw Error(ExitCode::kDataError, organ.where + "organ '" + organ.name + "': body.volume_drive drives the rest volume, so it needs " +
                                          (organ.body.volume_stiffness_Pa > 0
                                               ? std::string("a closed surface (this one is open or non-manifold: see the mesh report)")
                                               : std::string("body.volume_stiffness > 0")));
  }
}

}  // namespace

Model build_model(const OrganParams& organ, BodyParts parts, const ModelOptions& options) {
  Model m;
  set_regions(m, organ, options);
  set_particles(m, parts);
  build_springs(m, organ, parts);
  build_volume(m, organ, parts, options);
  add_interactions(m, options.interactions, parts.interaction_reach_m);
  add_tethers(m);
  if (options.solver.auto_substeps) {
    // solver.dt: auto - as many substeps as this body's stiffness needs at the world's step.
    m.substeps = std::max(1, static_cast<int>(std::ceil(options.dt_s / step_limits(m).max_substep_s - 1e-9)));
  }
  return m;
}

Model with_method(const Model& base, Method method) {
  Model m = base;
  m.method = method;
  return m;
}

double boundary_blend(const std::vector<RegionParams>& regions, int region_a, int region_b,
                      double RegionParams::*scale) {
  return 0.5 * ((region_a >= 0 ? regions[region_a].*scale : 1.0) + (region_b >= 0 ? regions[region_b].*scale : 1.0));
}

Model with_regions(const Model& base, const std::vector<RegionParams>& regions) {
  Model m = base;
  Springs& sp = m.springs;
  const auto stiffness = &RegionParams::stiffness_scale;
  for (int j = 0; j < sp.size(); ++j) {
    sp.compliance_m_per_N[j] *= boundary_blend(base.regions, sp.region_a[j], sp.region_b[j], stiffness) /
                                boundary_blend(regions, sp.region_a[j], sp.region_b[j], stiffness);
  }
  m.regions = regions;
  // A regular drive has no beat boundaries; an irregular one keeps the scene's seeded beats.
  for (std::size_t r = 0; r < regions.size() && r < m.beat_boundaries.size(); ++r) {
    if (regions[r].drive.irregularity == 0) m.beat_boundaries[r].clear();
  }
  return m;
}

void region_activations(const Model& model, double t_s, std::vector<double>& phi) {
  static const std::vector<double> kRegular;
  phi.resize(model.regions.size());
  for (std::size_t r = 0; r < phi.size(); ++r) {
    phi[r] = activation(model.regions[r].drive, t_s, model.ramp_s,
                        r < model.beat_boundaries.size() ? model.beat_boundaries[r] : kRegular);
  }
}

}  // namespace systole::sim
