#pragma once
// An organ: its mesh, placement, material, body, regions (selectors and drives) and
// training target. Every quantity in SI units, whatever unit the YAML used.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scene/drive.h"
#include "scene/origin.h"

namespace systole::scene {

// ---------------------------------------------------------------------------------------
// Regions: parts of an organ's surface with their own rhythm and stiffness.

enum class SelectorKind {
  kAll,        ///< Every vertex.
  kPart,       ///< A named part: a procedural organ's anatomical part, or a file's sub-mesh name.
  kSphere,     ///< Vertices within radius of center (organ space, after units and centring).
  kBox,        ///< Vertices inside the axis-aligned box [min, max].
  kHalfSpace,  ///< Vertices with dot(x - point, normal) >= 0.
};

struct Selector {
  SelectorKind kind = SelectorKind::kAll;
  std::string part;                                 ///< kPart
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< kSphere. unit: m
  double radius_m = 0;                              ///< kSphere. unit: m
  Eigen::Vector3d min = Eigen::Vector3d::Zero();     ///< kBox. unit: m
  Eigen::Vector3d max = Eigen::Vector3d::Zero();     ///< kBox. unit: m
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< kHalfSpace. unit: m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY(); ///< kHalfSpace (normalised). unit: 1
  Origin origin;
};

/// A compliant hold of a region towards its rest place (ligaments, the mediastinum):
/// zero-length springs from each of its particles to where it lies at rest, shifted by offset.
struct Tether {
  bool enabled = false;
  double stiffness_N_per_m = 0;  ///< For the whole region, shared by its particles. unit: N/m
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  ///< Anchor offset from rest (a preload). unit: m
};

struct Region {
  std::string name;
  /// Union of selectors. Empty: the part of the same name. Regions are applied in order,
  /// a later region taking the vertices it selects from an earlier one.
  std::vector<Selector> select;
  Drive drive;
  double stiffness_scale = 1;  ///< Multiplies the body's stiffness. unit: 1
  double damping_scale = 1;    ///< Multiplies the body's damping. unit: 1
  bool pinned = false;         ///< Fixed in place: costs nothing in the solve.
  int detail = 1;              ///< Reduced model only: the region's voxels split into detail^3 (1, 2 or 4).
  /// Pinned regions only: offsets from the rest position over time (a kinematic region,
  /// e.g. a vessel stub moved by breathing). Empty: the region stays at rest.
  std::vector<PathKey> motion;
  Tether tether;               ///< enabled: held by springs towards its rest place.
  bool has_color = false;
  Color color = Color(0.8, 0.3, 0.3);  ///< Used when has_color; else the organ's material.
  bool has_opacity = false;
  double opacity = 1;          ///< Used when has_opacity; else the material's. unit: 1, in [0, 1]
  Origin origin;
};

// ---------------------------------------------------------------------------------------
// Organs.

struct MeshSource {
  std::string file;        ///< A mesh file, resolved against the scene's folder by load(); or empty.
  std::string procedural;  ///< A generated organ: "heart" (more in mesh/procedural/), or empty.
  int detail = 3;          ///< Procedural level of detail, 1 (coarse) to 6 (fine).
  double unit_m = 1;       ///< Length of one file unit in metres (mm = 0.001). unit: m
  bool center = true;      ///< Move the file's bounding-box centre to the origin.
  Origin origin;
  Origin units_origin;     ///< Where `units` was given (a file line, or a -D); empty file: not given.
};

struct Transform {
  Eigen::Vector3d translate_m = Eigen::Vector3d::Zero();  ///< unit: m
  Eigen::Vector3d rotate_rad = Eigen::Vector3d::Zero();   ///< Euler X, then Y, then Z. unit: rad
  double scale = 1;                                       ///< unit: 1
};

struct Material {
  Color color = Color(0.72, 0.16, 0.14);
  double specular = 0.35;  ///< Strength of the highlight. unit: 1
  double shininess = 24;   ///< Blinn-Phong exponent. unit: 1
  double opacity = 1;      ///< 1 opaque, 0 invisible; below 1 drawn with order-independent transparency. unit: 1
};

/// A plane that cuts an organ open: the side dot(x - point, normal) < 0 is removed, and the
/// inside seen through the cut is drawn flat in cut_color.
/// A named plane of the anatomical heart (clip/sections.h places it from the heart's landmarks).
enum class Section {
  kNone,         ///< The plane is given by point and normal.
  kFourChamber,  ///< Through the long axis and both ventricles (the apical four-chamber view).
  kShortAxis,    ///< Across the long axis, mid-ventricle (the parasternal short-axis view).
};

struct ClipPlane {
  bool enabled = false;
  Section section = Section::kNone;
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  ///< A point on the plane, world space. unit: m
  Eigen::Vector3d normal = -Eigen::Vector3d::UnitZ();  ///< Points to the side kept (normalised). unit: 1
  Color cut_color = Color(0.93, 0.78, 0.62);           ///< sRGB of the cut face.
};

/// What a surface's colour shows. The colour maps are in render/color_map.h.
enum class ColorBy {
  kMaterial,    ///< The material colour, with region colours where a region sets one.
  kRegion,      ///< Every region its own colour: its `color`, else one of a fixed palette.
  kStrain,      ///< Per vertex, mean relative length change of its edges, (L - L0) / L0.
  kActivation,  ///< Per vertex, its region's drive activation phi(t) in [0, 1].
};

struct Body {
  double mass_kg = 0.3;           ///< Total mass, spread over vertices by area. unit: kg
  double stiffness_N_per_m = 400; ///< Spring stiffness of each surface edge. unit: N/m
  double damping_s = 0.01;        ///< Stiffness-proportional damping time (c = k * damping_s). unit: s
  double volume_stiffness_Pa = 20000;  ///< Bulk modulus of the enclosed volume; 0 = no volume constraint. unit: Pa
  double drag_per_s = 1.0;        ///< Velocity damping towards rest (the surrounding tissue). unit: 1/s
  double bending_N_per_m = 0;     ///< Stiffness of the springs across each edge (0: no bending). unit: N/m
  /// Reduced model: voxels along the longest side (0: every vertex a particle), or
  /// kLatticeAuto: world/ chooses from the mesh (world::choose_body). unit: 1
  int lattice = kLatticeAuto;
  static constexpr int kLatticeAuto = -1;
  /// Drives the rest volume, V0(t) = V0 (1 + amplitude * phi(t - delay)): lungs inflating.
  /// waveform kNone: a constant rest volume. Needs the volume constraint.
  Drive volume_drive;
  /// Muscle with fibres (the anatomical heart): the fibres' tension beside the active strain,
  /// a further fibre shortening 1 - fibre_tension c (sim/forces.h). unit: 1
  double fibre_tension = 0;
};

// ---------------------------------------------------------------------------------------
// Training target (train/, `systole tune`): rough motion the organ should learn to make
// by itself, and how to tune its regions to it.

/// One key-frame mesh: the organ's surface (same vertices, same order) at a time of the cycle.
struct TargetFrame {
  std::string file;   ///< Resolved against the scene's folder by load().
  double time_s = 0;  ///< Time within the target's period. unit: s
};

/// A region's size over one period, evenly spaced samples relative to the rest shape.
struct TargetCurve {
  std::string region;
  bool volume = false;          ///< Samples are relative volumes (else relative linear scale).
  std::vector<double> samples;  ///< unit: 1 (1 = rest)
  Origin origin;
};

/// A pair of matching points that starts a target's alignment (train/transfer.h).
struct TargetLandmark {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< On the target, in its file's coordinates. unit: the file's
  Eigen::Vector3d organ_m = Eigen::Vector3d::Zero();  ///< On the organ, in the scene. unit: m
};

struct TargetAlign {
  bool affine = false;                    ///< Any affine map (else a rigid motion and a uniform scale).
  std::vector<TargetLandmark> landmarks;  ///< Pairs starting the alignment (3 or more, or none).
};

struct Target {
  bool enabled = false;
  double rate_hz = 0;                  ///< Cycles per second the target (and the tuned drives) run at. unit: Hz
  std::vector<TargetFrame> frames;     ///< A key-frame mesh sequence over one period...
  std::vector<TargetCurve> curves;     ///< ...or per-region size curves...
  std::string animation;               ///< ...or an animated file of any mesh (glTF/GLB..., PC2/MDD + OBJ, a .pvd series); resolved by load().
  int animation_samples = 0;           ///< Poses sampled from the animation over one period; 0: its own keys where even (glTF), else 32.
  int cycles = 1;                      ///< Periods the animation holds; the one after `settle` (or its last) is the target.
  int piece = -1;                      ///< A ParaView series' piece (one per organ); -1: its only one.
  TargetAlign align;                   ///< How its rest surface is laid on the organ's.
  double unit_m = 0;                   ///< Length of one unit of the animation file; 0: the organ mesh's. unit: m
  double coupling_N_per_m = 5000;      ///< Stiffness tying each particle to its target while recording. unit: N/m
  int harmonics = 3;                   ///< Fourier harmonics of a fitted drive.
  std::vector<std::string> lock;       ///< Parameters kept as written: `param`, `region` or `region.param`.
  int budget = 300;                    ///< Playbacks the tuner may run.
  double settle_cycles = 2;            ///< Cycles run before the error is measured. unit: cycles
  double measure_cycles = 1;           ///< Cycles over which the error is measured. unit: cycles
  Origin origin;
};

/// The blood in an anatomical heart's ventricles (sim/circulation.h); absent: none.
struct Blood {
  bool enabled = false;             ///< The scene has the block.
  double aortic_pressure_Pa = 0;    ///< The left ventricle's afterload. unit: Pa
  double pulmonary_pressure_Pa = 0; ///< The right ventricle's. unit: Pa
  double aortic_elastance_Pa_per_m3 = 0;     ///< How the aortic pressure rises with the volume ejected. unit: Pa/m^3
  double pulmonary_elastance_Pa_per_m3 = 0;  ///< The pulmonary pressure's. unit: Pa/m^3
  double filling_pressure_Pa = 0;   ///< The atria's: an inflow valve opens below it. unit: Pa
  double chordae = 0;               ///< The share of the shut mitral valve's load its chordae carry. unit: 1
};

/// A bundle branch that does not conduct (docs/electrophysiology.md).
enum class BundleBranchBlock { kNone, kLeft, kRight };

/// The heart's own conduction system (electro/conduction.h): when enabled, every beat starts
/// at the sinus node and reaches each part of the muscle when the excitation does; absent:
/// each region's drive starts at its own delay.
struct Electrophysiology {
  bool enabled = false;  ///< The scene has the block.
  BundleBranchBlock block = BundleBranchBlock::kNone;
};

struct Organ {
  std::string name;
  MeshSource mesh;
  Transform transform;
  Material material;
  Body body;
  Blood blood;
  Electrophysiology electrophysiology;
  std::vector<Region> regions;
  Target target;                ///< enabled: `systole tune` fits the regions to it.
  ColorBy color_by = ColorBy::kMaterial;
  bool has_color_range = false;
  /// Values mapped to the ends of the colour map (strain, activation); default by color_by. unit: 1
  Eigen::Vector2d color_range = Eigen::Vector2d(-0.1, 0.1);
  ClipPlane clip;
  /// A static collider (a rib cage): drawn and touched by the other organs, never simulated.
  bool collider = false;
  Origin origin;
};

}  // namespace systole::scene
