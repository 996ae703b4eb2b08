#include "sim/myocardium.h"

#include <algorithm>

#include "sim/model.h"

namespace systole::sim {

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
  return body;
}

}  // namespace systole::sim
