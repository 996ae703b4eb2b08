#include "sim/myocardium.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "sim/model.h"

namespace systole::sim {
namespace {

// The valve of this chamber nearest a rim of its lining (centroid to centroid), or none:
// which cap the rim closes, inflow or outflow.
const mesh::Valve* nearest_valve(const mesh::Cavity& cavity, const mesh::Anatomy& anatomy,
                                 const std::vector<Eigen::Vector3d>& surface, const std::vector<int>& rim) {
  auto centroid = [&](const std::vector<int>& vertices) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : vertices) c += surface[static_cast<std::size_t>(v)];
    return Eigen::Vector3d(c / static_cast<double>(vertices.size()));
  };
  const Eigen::Vector3d rim_centre = centroid(rim);
  const mesh::Valve* nearest = nullptr;
  double nearest_m = 0;
  for (const mesh::Valve& valve : anatomy.valves) {
    if (valve.chamber != cavity.name || valve.vertices.empty()) continue;
    const double m = (centroid(valve.vertices) - rim_centre).norm();
    if (!nearest || m < nearest_m) nearest = &valve, nearest_m = m;
  }
  return nearest;
}

// Stores the chamber's points flat: each point's offset and its run of particle terms.
void store_points(Chamber& chamber, const std::vector<std::map<int, double>>& terms,
                  const std::vector<Eigen::Vector3d>& offsets) {
  chamber.point_offset.resize(3, static_cast<Eigen::Index>(offsets.size()));
  chamber.point_begin.push_back(0);
  for (std::size_t p = 0; p < terms.size(); ++p) {
    chamber.point_offset.col(static_cast<Eigen::Index>(p)) = offsets[p];
    for (const auto& [particle, weight] : terms[p]) {
      chamber.term_particle.push_back(particle);
      chamber.term_weight.push_back(weight);
    }
    chamber.point_begin.push_back(static_cast<int>(chamber.term_particle.size()));
  }
}

/// A ventricle's cavity over the body's particles: each lining vertex where the embedding
/// carries it, a cap across each annulus fanned from the rim's centre (mesh::cavity_volume's
/// closure), every triangle turned to face out of the blood. Each cap belongs to the valve
/// whose leaflets lie nearest its rim. The left ventricle's chordae pull on its lining at the
/// papillary muscles' bases: the mid-ventricular anterolateral and inferior segments (AHA 12
/// and 10; the anterolateral and posteromedial muscles).
Chamber chamber_of(const mesh::Cavity& cavity, const mesh::Anatomy& anatomy, const std::vector<Eigen::Vector3d>& surface,
                   const Embedding& e, const Eigen::Matrix3Xd& rest) {
  Chamber chamber;
  chamber.name = cavity.name;
  std::map<int, int> point_of;  // Render vertex -> point.
  std::vector<std::map<int, double>> terms;
  std::vector<Eigen::Vector3d> offsets;
  auto point = [&](int v) {
    auto [it, added] = point_of.try_emplace(v, static_cast<int>(terms.size()));
    if (added) {
      std::map<int, double> t;
      for (int k = 0; k < 8; ++k) t[e.node(k, v)] += e.weight(k, v);
      terms.push_back(std::move(t));
      offsets.push_back(e.offset.col(v));
    }
    return it->second;
  };
  for (const Eigen::Vector3i& t : cavity.lining) chamber.triangles.emplace_back(point(t[0]), point(t[2]), point(t[1]));
  for (const std::vector<int>& rim : cavity.rims) {
    const mesh::Valve* nearest = nearest_valve(cavity, anatomy, surface, rim);
    const int first = static_cast<int>(chamber.triangles.size());
    const int last = first + static_cast<int>(rim.size());
    if (nearest) (nearest->opens_on_filling ? chamber.inflow_cap : chamber.outflow_cap) = {first, last};
    std::map<int, double> centre;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    const double share = 1.0 / static_cast<double>(rim.size());
    for (int v : rim) {
      for (const auto& [particle, weight] : terms[point(v)]) centre[particle] += share * weight;
      offset += share * offsets[point(v)];
    }
    const int c = static_cast<int>(terms.size());
    terms.push_back(std::move(centre));
    offsets.push_back(offset);
    for (std::size_t i = 0; i < rim.size(); ++i) chamber.triangles.emplace_back(point(rim[i]), c, point(rim[(i + 1) % rim.size()]));
  }
  if (cavity.name == "left_ventricle") {
    const mesh::VentricleLandmarks& lv = anatomy.left_ventricle;
    for (std::size_t i = 0; i < lv.wall.size(); ++i) {
      if (lv.wall_segment[i] != 10 && lv.wall_segment[i] != 12) continue;
      if (auto it = point_of.find(lv.wall[i].first); it != point_of.end()) chamber.chordae_points.push_back(it->second);
    }
  }
  store_points(chamber, terms, offsets);
  chamber.rest_m3 = chamber_volume(chamber, rest);
  return chamber;
}

/// The ventricles' blood: every cavity a valve opens into, the left one against the aortic
/// pressure, the right one against the pulmonary.
Circulation circulation_of(const OrganParams& organ, const mesh::Anatomy& anatomy,
                           const std::vector<Eigen::Vector3d>& surface, const Embedding& e, const Eigen::Matrix3Xd& rest) {
  Circulation circulation;
  if (!organ.blood.enabled) return circulation;
  circulation.filling_Pa = organ.blood.filling_Pa;
  for (const mesh::Cavity& cavity : anatomy.cavities) {
    const bool ventricle = std::any_of(anatomy.valves.begin(), anatomy.valves.end(),
                                       [&](const mesh::Valve& v) { return v.chamber == cavity.name; });
    if (ventricle) {
      circulation.chambers.push_back(chamber_of(cavity, anatomy, surface, e, rest));
      const bool left = cavity.name == "left_ventricle";
      Chamber& chamber = circulation.chambers.back();
      chamber.afterload_Pa = left ? organ.blood.aortic_Pa : organ.blood.pulmonary_Pa;
      chamber.arterial_elastance_Pa_per_m3 =
          left ? organ.blood.aortic_elastance_Pa_per_m3 : organ.blood.pulmonary_elastance_Pa_per_m3;
      if (left) chamber.chordae_share = organ.blood.chordae;
    }
  }
  return circulation;
}

/// Each driven spring end takes its region's drive from when the excitation reaches its
/// particle (to the millisecond: finer than any solver step, and the ends of one front
/// share a slot).
void excite_drives(Model& model, const electro::Excitation& excitation) {
  std::map<std::pair<int, long>, int> slot_of;
  const auto slot = [&](int particle) {
    const int r = model.vertex_region[static_cast<std::size_t>(particle)];
    const double t = excitation.activation_s[static_cast<std::size_t>(particle)];
    if (r < 0 || model.regions[static_cast<std::size_t>(r)].drive.waveform == Waveform::kNone || std::isnan(t)) return r;
    const auto [it, added] = slot_of.try_emplace({r, std::lround(t * 1000)}, model.excited.size());
    if (added) {
      model.excited.region.push_back(r);
      model.excited.delay_s.push_back(double(std::lround(t * 1000)) / 1000);
    }
    return static_cast<int>(model.regions.size()) + it->second;
  };
  Springs& sp = model.springs;
  for (int j = 0; j < sp.size(); ++j) {
    sp.contraction_a.push_back(slot(sp.a[j]));
    sp.contraction_b.push_back(slot(sp.b[j]));
  }
}

}  // namespace

ReducedBody build_myocardium_model(const OrganParams& organ, const mesh::OrganGeometry& geometry,
                                   const ModelOptions& options) {
  const mesh::Myocardium& myo = geometry.mesh.anatomy.myocardium;
  const int n = static_cast<int>(myo.nodes.size());
  BodyParts parts;
  parts.rest_positions.resize(3, n);
  parts.mass_kg.resize(n);
  double volume = 0;
  for (double v : myo.node_volume_m3) volume += v;
  for (int i = 0; i < n; ++i) {
    parts.rest_positions.col(i) = myo.nodes[i];
    // A node of the glue or a vessel's end may have no cell volume: a tenth of the mean.
    parts.mass_kg[i] = organ.body.mass_kg * std::max(myo.node_volume_m3[i] / volume, 0.1 / n);
  }
  parts.mass_kg *= organ.body.mass_kg / parts.mass_kg.sum();
  parts.particle_region = geometry.node_region;
  parts.springs = myo.springs;
  parts.stretch_count = static_cast<int>(myo.springs.size());
  for (double w : myo.spring_weight) parts.spring_stiffness_N_per_m.push_back(w * organ.body.stiffness_N_per_m);
  parts.fibre_share = myo.fibre_share;
  parts.normal_share = myo.normal_share;
  parts.cross_fibre = myo.cross_fibre;
  // An interaction reaches the nodes of the cells under the surface it touches.
  parts.interaction_reach_m = 0.01;

  ReducedBody body;
  const int vertices = static_cast<int>(myo.vertex_nodes.size());
  Embedding& e = body.embedding;
  e.node.resize(8, vertices);
  e.weight.resize(8, vertices);
  e.offset.resize(3, vertices);
  for (int v = 0; v < vertices; ++v) {
    Eigen::Vector3d carried = Eigen::Vector3d::Zero();
    for (int k = 0; k < 8; ++k) {
      e.node(k, v) = myo.vertex_nodes[v][k];
      e.weight(k, v) = myo.vertex_weights[v][k];
      carried += e.weight(k, v) * myo.nodes[e.node(k, v)];
    }
    e.offset.col(v) = geometry.mesh.surface.positions[v] - carried;
  }
  body.model = build_model(organ, std::move(parts), options);
  if (organ.electrophysiology) {
    body.model.excitation = std::make_shared<const electro::Excitation>(electro::excite(geometry.mesh, organ.conduction));
    excite_drives(body.model, *body.model.excitation);
  }
  body.model.circulation =
      circulation_of(organ, geometry.mesh.anatomy, geometry.mesh.surface.positions, e, body.model.rest_positions);
  return body;
}

}  // namespace systole::sim
