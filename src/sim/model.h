#pragma once
// sim::Model: everything about a soft body that stepping never changes - rest shape,
// masses, constraints, regions and their drives. Built once from an organ's geometry and
// parameters (MuJoCo's mjModel / mjData split: the changing part is sim::State). Nothing
// writes a Model after build_model (or with_regions) returns: every solver takes it const.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mesh/geometry.h"
#include "sim/circulation.h"
#include "sim/constraints/volume.h"
#include "sim/params.h"

namespace systole::sim {

/// Distance constraints ("springs") in structure-of-arrays form, ordered by colour so
/// that the springs of one colour share no particle: a colour can be solved in any order
/// or in parallel with bit-identical results.
struct Springs {
  std::vector<int> a, b;                 ///< Particle indices.
  std::vector<double> rest_m;            ///< Rest length L0. unit: m
  std::vector<double> compliance_m_per_N;  ///< 1 / stiffness. unit: m/N
  std::vector<double> damping_s;         ///< Stiffness-proportional damping time. unit: s
  std::vector<int> region_a, region_b;   ///< Drive region of each end (-1: undriven).
  /// With electrophysiology: each end's entry in State::region_contraction, its region's
  /// drive started when the excitation reaches it (Model::excited); empty: region_a, region_b.
  std::vector<int> contraction_a, contraction_b;
  /// Muscle with fibres (a myocardium): per spring, the squared cosine of its direction with
  /// the fibre and with the sheet normal, and the cross-fibre ratio k; a fibre share below 0,
  /// or empty vectors: no fibres (sim/forces.h, driven_rest_length).
  std::vector<double> fibre_share, normal_share, cross_fibre;
  /// The fibres' own tension beside the active strain: a fibre's rest length shortens by a
  /// further factor 1 - fibre_tension c that the other directions do not take up (sim/forces.h).
  double fibre_tension = 0;
  std::vector<int> color_begin;          ///< Springs of colour c: [color_begin[c], color_begin[c+1]).
  int stretch_count = 0;                 ///< Springs on surface edges.
  int bending_count = 0;                 ///< Springs across edges (between the two opposite corners).

  int size() const { return static_cast<int>(a.size()); }
  int colors() const { return static_cast<int>(color_begin.size()) - 1; }
};

/// Keeps the enclosed volume of a closed surface near a (possibly driven) rest volume.
struct VolumeConstraint {
  bool enabled = false;
  std::vector<Eigen::Vector3i> triangles;  ///< The closed surface, outward CCW.
  double rest_m3 = 0;                      ///< V0, the rest volume undriven. unit: m^3
  double compliance_m5_per_N = 0;          ///< V0 / bulk modulus, for C = V - V0(t). unit: m^5/N
  Drive drive;                      ///< V0(t) = V0 (1 + amplitude phi(t)); kNone: constant.
  std::vector<double> beat_boundaries;     ///< The drive's seeded irregular beats, else empty.
};

/// A scripted push: a force spread over a patch of particles during [start_s, end_s), or,
/// with a drive, scaled by the drive's phi(t) all the time.
struct Poke {
  std::vector<int> particles;
  Eigen::Vector3d force_per_particle_N = Eigen::Vector3d::Zero();  ///< unit: N
  double start_s = 0;  ///< unit: s
  double end_s = 0;    ///< unit: s
  Drive drive;  ///< waveform kNone: a one-off push.
};

/// A patch of particles held by stiff zero-length springs to a handle that moves along a
/// path; active from the first key's time to the last's, then let go.
struct Grab {
  std::vector<int> particles;
  std::vector<Eigen::Vector3d> offsets_m;  ///< Each particle's rest offset from the handle. unit: m
  std::vector<PathKey> path;
  double compliance_m_per_N = 0;           ///< unit: m/N
};

struct Embedding;  // sim/reduced.h

/// Zero-length attachments of every free particle (or embedded surface point) to a moving target position: how
/// training couples the body to key-frame motion (train/). Each is three XPBD
/// constraints C = x_i - target_i(t) (Macklin et al. 2016, eq. 18, target inverse mass 0),
/// so State::attachment_lambda / h^2 is the force the coupling exerts. XPBD only. Not part
/// of the Model: whoever couples a body passes it to sim::step beside the model.
struct Attachments {
  /// Writes every attached point's target at time t into `out` (3 x points); empty: none. unit: m
  std::function<void(double t_s, Eigen::Matrix3Xd& out)> target;
  double compliance_m_per_N = 0;  ///< unit: m/N
  /// The attached points: the render surface embedded in the body (a lattice's or a
  /// myocardium's), each C = sum_k w_k x_k + offset - target, which moves its cell's corners
  /// by their weights as contact does; null or empty: every particle itself.
  const Embedding* points = nullptr;

  bool enabled() const { return static_cast<bool>(target); }
};

/// A pinned region that moves along a prescribed path: its particles are placed, not
/// simulated (inverse mass 0), and pull their neighbours along through the springs.
struct KinematicRegion {
  std::vector<int> particles;
  std::vector<PathKey> motion;  ///< Offsets from the rest positions over time.
};

/// With electrophysiology (electro/conduction.h): contraction slots, each a region's drive
/// started when the excitation reaches the particles that use it, delay_s after the sinus
/// node fires (to the millisecond). Slot k's contraction is
/// State::region_contraction[regions.size() + k].
struct ExcitedDrives {
  std::vector<int> region;
  std::vector<double> delay_s;  ///< unit: s

  int size() const { return static_cast<int>(region.size()); }
};

struct Model {
  std::string name;                         ///< The organ's name, for messages.
  Method method = Method::kXpbd;
  int substeps = 4;                         ///< Per step; chosen by the builder when solver.auto_substeps.
  int iterations = 2;                       ///< Projective: local/global iterations per substep.
  int threads = 1;                          ///< Threads for the spring loops (same result at any count).
  Eigen::Matrix3Xd rest_positions;          ///< unit: m
  Eigen::VectorXd inverse_mass;             ///< unit: 1/kg; 0 = pinned.
  Springs springs;
  VolumeConstraint volume;
  Circulation circulation;                  ///< The ventricles' blood (anatomical heart); empty: none.
  std::vector<RegionParams> regions;       ///< Drives by region index.
  ExcitedDrives excited;                    ///< Empty without electrophysiology.
  /// The excitation that times them (per particle: the body is the myocardium); null without.
  std::shared_ptr<const electro::Excitation> excitation;
  /// Per region: the beat boundaries in cycles when its drive is irregular (seeded), else empty.
  std::vector<std::vector<double>> beat_boundaries;
  std::vector<int> vertex_region;           ///< Per particle; -1 = undriven body.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< unit: m/s^2
  double drag_per_s = 0;                    ///< unit: 1/s
  double ramp_s = 0;                        ///< Length of the clip, over which rate ramps run. unit: s
  double rest_extent_m = 0;                 ///< Bounding-box diagonal of the rest shape. unit: m
  std::vector<Poke> pokes;
  std::vector<Grab> grabs;
  std::vector<KinematicRegion> kinematic;
  Floor floor;

  int particle_count() const { return static_cast<int>(rest_positions.cols()); }
};

/// The particles and springs of a body before regions, drives, volume and interactions are
/// attached: every surface vertex (build_model below), a lattice (sim/reduced.h) or a
/// generator's myocardium (sim/myocardium.h).
struct BodyParts {
  Eigen::Matrix3Xd rest_positions;                ///< unit: m
  Eigen::VectorXd mass_kg;                        ///< Per particle. unit: kg
  std::vector<int> particle_region;               ///< Per particle: region index, or -1 (undriven body).
  std::vector<std::pair<int, int>> springs;       ///< Stretch springs first, then bending springs.
  std::vector<double> spring_stiffness_N_per_m;   ///< Per spring, before region scales. unit: N/m
  int stretch_count = 0;                          ///< How many of `springs` are stretch springs.
  std::vector<double> fibre_share, normal_share, cross_fibre;  ///< Per spring (Springs); empty: no fibres.
  std::vector<Eigen::Vector3i> volume_triangles;  ///< Closed, outward surface; empty: it encloses nothing.
  double volume_stiffness_scale = 1;  ///< Multiplies the bulk modulus (a lattice's hull is not the mesh). unit: 1
  double volume_drive_scale = 1;      ///< Multiplies body.volume_drive's amplitude (idem). unit: 1
  double interaction_reach_m = 0;     ///< Added to an interaction's radius when choosing its particles. unit: m
};

/// Lumped masses: each triangle gives a third of its share of the organ's mass to each corner. unit: kg
Eigen::VectorXd lumped_masses(const Eigen::Matrix3Xd& x, const std::vector<Eigen::Vector3i>& triangles,
                              double total_mass_kg);

/// The parts of the full model: every surface vertex a particle with its area's share of
/// the mass, springs on every edge (and across every interior edge when the body bends),
/// the surface as the volume constraint's when it encloses a volume.
BodyParts surface_body(const OrganParams& organ, const mesh::OrganGeometry& geometry);

/// The body of one organ from given parts (what build_model does after taking the parts
/// from the surface). Same errors as build_model.
Model build_model(const OrganParams& organ, BodyParts parts, const ModelOptions& options);

/// The same body with other region drives and stiffness scales (training tries many):
/// spring compliances follow the new scales with build_model's blending across region
/// boundaries; an irregular drive keeps the seeded beats of `base`, a regular one has none.
Model with_regions(const Model& base, const std::vector<RegionParams>& regions);

/// The same body stepped by another solver (training records its coupling with XPBD).
Model with_method(const Model& base, Method method);

/// The mean of a spring's two end regions' scale (`scale` picks stiffness or damping; an
/// undriven end counts 1): how region parameters blend across a boundary, so neighbouring
/// regions of very different stiffness share a transition ring instead of a seam. unit: 1
double boundary_blend(const std::vector<RegionParams>& regions, int region_a, int region_b,
                      double RegionParams::*scale);

/// Every region's activation phi(t) at organ time t_s (its drive, the model's ramp, its
/// seeded beats), into phi (one per region): what `color_by: activation` shows.
void region_activations(const Model& model, double t_s, std::vector<double>& phi);

/// Builds the body of one organ, every surface vertex a particle. Throws Error(kDataError) when an interaction touches no
/// particle (naming it and where it was written).
Model build_model(const OrganParams& organ, const mesh::OrganGeometry& geometry, const ModelOptions& options);

}  // namespace systole::sim
