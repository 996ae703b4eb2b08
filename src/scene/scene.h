#pragma once
// The validated scene: plain structs, every quantity in SI units (metres, seconds,
// hertz, radians, kilograms, newtons) whatever unit the YAML used. Built once by
// scene::load() and never changed afterwards; every default lives here, so a scene only
// says what differs (docs/scenes.md is the reference of every key).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace systole::scene {

/// Where a value was written: for error messages that point back into the YAML.
struct Origin {
  std::string file;  ///< Scene path, or "-D key=value" for a command-line override.
  int line = 0;      ///< 1-based; 0 when unknown.
  int column = 0;    ///< 1-based; 0 when unknown.
};

/// An sRGB colour as users pick them ("#b8322a" or [0.72, 0.2, 0.16]), each channel in
/// [0, 1]; render/ converts to linear light for shading and back for output.
using Color = Eigen::Vector3d;

// ---------------------------------------------------------------------------------------
// Drive: the periodic activation that shortens a region's springs,
// L(t) = L0 * (1 - amplitude * phi(t - delay)), phi in [0, 1] for the templates.

enum class Waveform {
  kNone,       ///< No drive: the region is passive.
  kSine,       ///< phi = (1 - cos(2 pi f t + phase)) / 2.
  kFourier,    ///< phi = 1/2 + sum_k a_k cos(2 pi k f t + phase_k), harmonics from k = 1.
  kCardiac,    ///< Raised-cosine contraction over the systolic fraction of each beat.
  kBreathing,  ///< Asymmetric: raised-cosine inhale over inhale_fraction, slower exhale.
  kSamples,    ///< A table of phi over one period, interpolated periodically.
};

struct Harmonic {
  double amplitude = 0;  ///< Relative to the drive amplitude. unit: 1
  double phase_rad = 0;  ///< unit: rad
};

struct Drive {
  Waveform waveform = Waveform::kNone;
  double rate_hz = 0;       ///< Cycles per second at the start of the clip. unit: Hz
  double rate_end_hz = 0;   ///< When > 0, the rate ramps linearly to this by the clip's end. unit: Hz
  double amplitude = 0;     ///< Fraction of rest length removed at phi = 1. unit: 1, in [0, 1)
  double phase_rad = 0;     ///< unit: rad
  double delay_s = 0;       ///< Activation delay (atria before ventricles). unit: s
  std::vector<Harmonic> harmonics;  ///< kFourier: harmonic k = index + 1.
  double systolic_fraction = 0.35;  ///< kCardiac: part of the period spent contracting. unit: 1
  double inhale_fraction = 0.4;     ///< kBreathing: part of the period spent inhaling. unit: 1
  std::vector<double> samples;      ///< kSamples: phi over one period, evenly spaced.
  double irregularity = 0;          ///< Seeded beat-to-beat jitter of the period (0 = regular). unit: 1
};

/// A position at a time: a key of a grab's handle path or of a kinematic region's motion,
/// interpolated smoothly (Catmull-Rom) between keys and held outside them.
struct PathKey {
  double time_s = 0;                                   ///< unit: s
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< unit: m
};

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
  bool has_color = false;
  Color color = Color(0.8, 0.3, 0.3);  ///< Used when has_color; else the organ's material.
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
};

struct Body {
  double mass_kg = 0.3;           ///< Total mass, spread over vertices by area. unit: kg
  double stiffness_N_per_m = 400; ///< Spring stiffness of each surface edge. unit: N/m
  double damping_s = 0.01;        ///< Stiffness-proportional damping time (c = k * damping_s). unit: s
  double volume_stiffness_Pa = 20000;  ///< Bulk modulus of the enclosed volume; 0 = no volume constraint. unit: Pa
  double drag_per_s = 1.0;        ///< Velocity damping towards rest (the surrounding tissue). unit: 1/s
  double bending_N_per_m = 0;     ///< Stiffness of the springs across each edge (0: no bending). unit: N/m
  int lattice = 0;                ///< Reduced model: voxels along the longest side (0: every vertex a particle). unit: 1
  /// Drives the rest volume, V0(t) = V0 (1 + amplitude * phi(t - delay)): lungs inflating.
  /// waveform kNone: a constant rest volume. Needs the volume constraint.
  Drive volume_drive;
};

struct Organ {
  std::string name;
  MeshSource mesh;
  Transform transform;
  Material material;
  Body body;
  std::vector<Region> regions;
  Origin origin;
};

// ---------------------------------------------------------------------------------------
// Solver, view and output.

enum class SolverMethod { kXpbd, kExplicit, kImplicit };

struct Solver {
  SolverMethod method = SolverMethod::kXpbd;
  bool auto_dt = false;        ///< Choose dt from the drive and stiffness (sim core issue).
  double dt_s = 1.0 / 240.0;   ///< Step size. unit: s
  int substeps = 4;            ///< XPBD substeps per step. unit: 1
  int threads = 1;             ///< Threads for the simulation's spring loops; the result is the same at any count.
  Origin origin;
};

struct Camera {
  Eigen::Vector3d position_m = Eigen::Vector3d(0, 0, 0.4);  ///< unit: m
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();       ///< unit: m
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();            ///< unit: 1
  double fov_rad = 0.6981317007977318;                      ///< Vertical field of view (40 deg). unit: rad
};

struct Light {
  Eigen::Vector3d direction = Eigen::Vector3d(-0.4, -0.6, -1.0);  ///< Direction the light travels. unit: 1
  Color color = Color(1, 1, 1);
  double intensity = 1;  ///< unit: 1
};

/// How edges are smoothed. FXAA is a post pass on the CPU (render/fxaa.h); MSAA shades
/// 2 or 4 samples per pixel, which costs llvmpipe far more (docs/performance.md).
enum class Antialias { kOff, kFxaa, kMsaa2, kMsaa4 };

/// Encoder settings by purpose; each names an x264 preset and CRF (Output::crf, ::preset),
/// chosen by measurement (docs/performance.md).
enum class Quality {
  kDraft,     ///< Fastest encode, larger files: for iterating on a scene.
  kStandard,  ///< For sharing and teaching.
  kArchival,  ///< Smallest artefacts, slower encode: for keeping.
};

struct Output {
  std::string file;        ///< Video path; empty: out/<scene name>.mp4 beside the working dir.
  int width = 1280;        ///< unit: px, even
  int height = 720;        ///< unit: px, even
  double fps = 30;         ///< unit: 1/s
  double duration_s = 10;  ///< unit: s
  Quality quality = Quality::kStandard;
  int crf = 20;            ///< x264 constant rate factor, 0 (lossless) to 51; default: the quality's.
  std::string preset = "veryfast";  ///< x264 preset; default: the quality's.
  Antialias antialias = Antialias::kFxaa;
  Color background = Color(0.06, 0.07, 0.09);

  int frame_count() const;  ///< round(duration * fps).
};

// ---------------------------------------------------------------------------------------
// Scripted interactions and contact.

enum class InteractionKind {
  kPoke,  ///< A force on the vertices near a point, over an interval.
  kGrab,  ///< The vertices near a point follow a handle along a path, then are let go.
};

struct Interaction {
  InteractionKind kind = InteractionKind::kPoke;
  std::string organ;                                 ///< Name of the organ touched.
  Eigen::Vector3d at_m = Eigen::Vector3d::Zero();    ///< Centre of the touched patch, world space at rest. unit: m
  double radius_m = 0.01;                            ///< Vertices within this distance of at_m are touched. unit: m
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero(); ///< kPoke: total force, shared by the patch's vertices. unit: N
  double start_s = 0;                                ///< kPoke: when the push starts. unit: s
  double duration_s = 0.1;                           ///< kPoke: how long it lasts. unit: s
  Drive drive;                                       ///< kPoke: when set, the force follows phi(t) all clip long (a periodic push).
  std::vector<PathKey> path;                         ///< kGrab: the handle's path, smoothly interpolated; released after the last key.
  double stiffness_N_per_m = 2000;                   ///< kGrab: stiffness holding each vertex to the handle. unit: N/m
  Origin origin;
};

/// A plane the organs cannot pass (a table, the diaphragm's floor).
struct Floor {
  bool enabled = false;
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  ///< A point on the plane. unit: m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< Points to the free side (normalised). unit: 1
};

// ---------------------------------------------------------------------------------------
// Teaching overlays drawn on each frame (src/overlay/, docs/teaching-visuals.md). Sizes are
// pixels of a 720-line frame, scaled with output.height.

enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

struct LabelsOverlay {
  bool enabled = false;
  std::string organ;                 ///< Empty: every organ.
  std::vector<std::string> regions;  ///< Empty: every region (`all`).
  int size_px = 16;                  ///< Text height. unit: px at 720 lines
  Origin origin;
};

struct LegendOverlay {
  bool enabled = false;
  std::string organ;                 ///< Empty: the first organ.
  Corner position = Corner::kTopLeft;
  int size_px = 14;                  ///< unit: px at 720 lines
  Origin origin;
};

enum class TraceSignal {
  kVolume,      ///< The organ's enclosed volume, as simulated.
  kActivation,  ///< A region's drive phi(t).
  kEcg,         ///< A synthetic P-QRS-T complex at each beat of a region's drive.
};

struct TraceOverlay {
  TraceSignal signal = TraceSignal::kVolume;
  std::string organ;                 ///< Empty: the first organ.
  std::string region;                ///< kActivation, kEcg: the region whose drive is shown (kEcg: the ventricles').
  std::string atria;                 ///< kEcg: a region whose beats give the P waves; empty: 160 ms before each R.
  Corner position = Corner::kBottomRight;
  int width_px = 360, height_px = 110;  ///< unit: px at 720 lines
  double window_s = 3;               ///< Sweep width; 0: the whole clip. unit: s
  Origin origin;
};

struct Overlay {
  std::string title;                 ///< Across the top; empty: none.
  int title_size_px = 26;            ///< unit: px at 720 lines
  LabelsOverlay labels;
  LegendOverlay legend;
  std::vector<TraceOverlay> traces;  ///< Insets; several in one corner stack.

  bool empty() const { return title.empty() && !labels.enabled && !legend.enabled && traces.empty(); }
};

struct Scene {
  std::string path;         ///< The YAML file it came from.
  std::string name;         ///< File stem: names default outputs.
  std::uint64_t seed = 1;   ///< Seeds every random choice (irregular rhythms, tuning).
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< unit: m/s^2
  std::vector<Organ> organs;
  std::vector<Interaction> interactions;
  Floor floor;
  Solver solver;
  Camera camera;
  std::vector<Light> lights;
  Output output;
  Overlay overlay;
};

}  // namespace systole::scene
