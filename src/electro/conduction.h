#pragma once
// The heart's conduction system and the excitation it spreads: when each particle of the
// anatomical heart's myocardium depolarises after the sinus node fires, and how long it
// stays depolarised (docs/electrophysiology.md).
//
// Pathway: sinus node -> atrial muscle (faster along Bachmann's bundle to the left atrium)
// -> AV node (the delay) -> His bundle -> left and right bundle branches -> a fast
// endocardial Purkinje layer in each ventricle -> the ventricular muscle. The fibrous ring
// between atria and ventricles conducts nothing: the AV node is the only way through.
// Activation times are an eikonal solve on the myocardium's graph (Dijkstra's ordered
// front over its springs, each spring's travel time its length over the speed along it:
// faster along the fibres than across them), as the reaction-eikonal models compute it
// (Neic et al. 2017, "Efficient computation of electrograms and ECGs in human whole heart
// simulations using a reaction-eikonal model", J Comput Phys 346:191).

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace systole::electro {

enum class Tissue : char { kNone, kAtrium, kVentricle };

/// A bundle branch that conducts nothing: its ventricle's Purkinje layer is reached only
/// through the septum's muscle, late.
enum class Block { kNone, kLeftBundle, kRightBundle };

/// Conduction speeds and delays, each from the literature (docs/electrophysiology.md).
struct ConductionParams {
  double atrial_mps = 1.0;         ///< Atrial muscle. unit: m/s
  double bachmann_mps = 1.7;       ///< Bachmann's bundle, sinus node to the left atrium. unit: m/s
  double av_node_s = 0.085;        ///< Through the AV node. unit: s
  double bundle_mps = 2.0;         ///< His bundle and its branches. unit: m/s
  double purkinje_mps = 2.5;       ///< The endocardial Purkinje layer. unit: m/s
  double fibre_mps = 0.6;          ///< Ventricular muscle along the fibres. unit: m/s
  double cross_fibre_mps = 0.25;   ///< Across them. unit: m/s
  /// The Purkinje layer covers the endocardium from the apex to this share of the way to the
  /// annulus; the base's endocardium has none. unit: 1
  double purkinje_reach = 0.9;
  Block block = Block::kNone;
};

/// The excitation of one beat, per myocardium node, timed from the sinus node's firing.
struct Excitation {
  std::vector<Tissue> tissue;
  std::vector<double> activation_s;  ///< When the node depolarises; NaN where not excitable. unit: s
  /// How long it stays depolarised at a 1-s cycle (endocardium longer than epicardium, apex
  /// longer than base); action_potential_s() scales it with the rate. unit: s
  std::vector<double> duration_1s_s;
  double av_node_s = 0;  ///< When the excitation reaches the AV node. unit: s
  double his_s = 0;      ///< When it leaves the AV node into the His bundle. unit: s
  int sinus_node = -1, av_node = -1, his_node = -1;

  bool excitable(int node) const { return tissue[static_cast<std::size_t>(node)] != Tissue::kNone; }
};

/// The excitation of the anatomical heart's myocardium (mesh.anatomy.myocardium, with its
/// part names). Throws common/error.h's Error when the mesh has no myocardium or no atria,
/// ventricles or septum to build the pathway on.
Excitation excite(const mesh::OrganMesh& mesh, const ConductionParams& params);

/// A node's action-potential duration at cycle length `cycle_s`: its 1-s duration scaled
/// by restitution, (cycle_s / 1 s)^(1/3) (Fridericia 1920's rate dependence of the QT
/// interval, which the action potentials make). unit: s
double action_potential_s(double duration_1s_s, double cycle_s);

}  // namespace systole::electro
