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
struct ClipPlane {
  bool enabled = false;
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
  int lattice = 0;                ///< Reduced model: voxels along the longest side (0: every vertex a particle). unit: 1
  /// Drives the rest volume, V0(t) = V0 (1 + amplitude * phi(t - delay)): lungs inflating.
  /// waveform kNone: a constant rest volume. Needs the volume constraint.
  Drive volume_drive;
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

struct Target {
  bool enabled = false;
  double rate_hz = 0;                  ///< Cycles per second the target (and the tuned drives) run at. unit: Hz
  std::vector<TargetFrame> frames;     ///< A key-frame mesh sequence over one period...
  std::vector<TargetCurve> curves;     ///< ...or per-region size curves...
  std::string animation;               ///< ...or an animated mesh file (morph targets, skinning); resolved by load().
  int animation_samples = 32;          ///< Poses sampled from the animation over one period.
  double coupling_N_per_m = 5000;      ///< Stiffness tying each particle to its target while recording. unit: N/m
  int harmonics = 3;                   ///< Fourier harmonics of a fitted drive.
  std::vector<std::string> lock;       ///< Parameters kept as written: `param`, `region` or `region.param`.
  int budget = 300;                    ///< Playbacks the tuner may run.
  double settle_cycles = 2;            ///< Cycles run before the error is measured. unit: cycles
  double measure_cycles = 1;           ///< Cycles over which the error is measured. unit: cycles
  Origin origin;
};

struct Organ {
  std::string name;
  MeshSource mesh;
  Transform transform;
  Material material;
  Body body;
  std::vector<Region> regions;
  Target target;                ///< enabled: `systole tune` fits the regions to it.
  ColorBy color_by = ColorBy::kMaterial;
  bool has_color_range = false;
  /// Values mapped to the ends of the colour map (strain, activation); default by color_by. unit: 1
  Eigen::Vector2d color_range = Eigen::Vector2d(-0.1, 0.1);
  ClipPlane clip;
  Origin origin;
};

// ---------------------------------------------------------------------------------------
// Solver, view and output.

enum class SolverMethod { kXpbd, kExplicit, kImplicit };

/// The name the scene gives a solver ("xpbd", "explicit", "implicit").
inline const char* method_name(SolverMethod m) {
  switch (m) {
    case SolverMethod::kXpbd: return "xpbd";
    case SolverMethod::kExplicit: return "explicit";
    case SolverMethod::kImplicit: return "implicit";
  }
  return "?";
}

struct Solver {
  SolverMethod method = SolverMethod::kXpbd;
  bool auto_dt = false;        ///< Choose dt from the drive and stiffness (sim core issue).
  double dt_s = 1.0 / 240.0;   ///< Step size. unit: s
  int substeps = 4;            ///< XPBD substeps per step. unit: 1
  int threads = 1;             ///< Threads for the simulation's spring loops; the result is the same at any count.
  Origin origin;
};

/// A key of a camera path: where the eye is and what it looks at, at a time.
struct CameraKey {
  double time_s = 0;                                     ///< unit: s
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< unit: m
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();    ///< unit: m
};

/// A turntable: the eye turns about the axis through the target at a constant speed.
struct Orbit {
  bool enabled = false;
  double speed_rad_per_s = 0.3490658503988659;  ///< 20 deg/s; negative turns the other way. unit: rad/s
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  ///< Normalised. unit: 1
};

/// The camera at time 0 (position, target) and how it moves: fixed, an orbit, or a path
/// (app/camera_motion.h gives the camera at any time).
struct Camera {
  Eigen::Vector3d position_m = Eigen::Vector3d(0, 0, 0.4);  ///< unit: m
  Eigen::Vector3d target_m = Eigen::Vector3d::Zero();       ///< unit: m
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();            ///< unit: 1
  double fov_rad = 0.6981317007977318;                      ///< Vertical field of view (40 deg). unit: rad
  Orbit orbit;
  std::vector<CameraKey> path;  ///< When not empty: Catmull-Rom through the keys, held outside them.
};

/// One panel of a split screen: its camera, which organs it shows, an optional cut.
struct View {
  bool has_camera = false;
  Camera camera;                     ///< Used when has_camera; else the scene's camera.
  std::vector<std::string> organs;   ///< Organ names shown; empty: every organ.
  ClipPlane clip;                    ///< Cuts the view's organs that have no clip of their own.
  std::string title;                 ///< Caption for the overlay (not drawn by render/).
  Origin origin;
};

/// A view's place in the frame, in pixels, origin at the top left. unit: px
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/// The views laid out as a grid over a width x height frame: one row for up to 3 views,
/// else ceil(sqrt(n)) columns; the last pixel column or row absorbs the rounding.
std::vector<PixelRect> view_rectangles(int width, int height, int view_count);

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

/// The video file's container and codec (docs/teaching-visuals.md, "Timing and formats").
enum class Format {
  kAuto,  ///< From output.file's extension; .mp4 when there is no file.
  kMp4,   ///< H.264 in MP4: plays everywhere.
  kMkv,   ///< FFV1 in Matroska: lossless RGB, for archives.
  kWebm,  ///< VP9 in WebM: for web pages.
  kGif,   ///< Animated GIF with one palette: for slides.
};

struct Output {
  std::string file;        ///< Video path; empty: out/<scene name>.<format's extension>.
  Format format = Format::kAuto;  ///< After loading never kAuto: resolved from `file`.
  int width = 1280;        ///< unit: px, even
  int height = 720;        ///< unit: px, even
  double fps = 30;         ///< unit: 1/s
  double duration_s = 10;  ///< Organ time shown, after loading a whole number of loops when `loop`. unit: s
  /// Video seconds per second of organ time: 4 shows a beat four times slower. The body is
  /// simulated at its true rate; frame k shows organ time start_s + k * frame_period_s().
  double slow_motion = 1;  ///< unit: 1
  /// Snap the clip to whole cycles of the slowest drive so its last frame flows into its first.
  bool loop = false;
  int settle_cycles = 2;   ///< loop: cycles (of the slowest drive) simulated before the clip starts, at least. unit: 1
  // Resolved on loading (scene::load), not keys:
  int start_frame = 0;       ///< loop: frames simulated before the clip's frame 0 (whole loops). unit: frames
  Quality quality = Quality::kStandard;
  int crf = 20;            ///< x264 constant rate factor, 0 (lossless) to 51; default: the quality's.
  std::string preset = "veryfast";  ///< x264 preset; default: the quality's.
  Antialias antialias = Antialias::kFxaa;
  Color background = Color(0.06, 0.07, 0.09);

  int frame_count() const;  ///< Frames of the clip (title cards not counted): round(duration * fps * slow_motion).
  /// Organ time between two frames: 1 / (fps * slow_motion), or for a loop duration /
  /// frame_count() exactly (the playback rate then differs by less than 1 / (2 frames)). unit: s
  double frame_period_s() const;
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
// Title cards and captions (app/cards.h draws them).

/// Full-frame text on the background colour, shown before the clip.
struct Card {
  std::string text;              ///< Lines separated by "\n"; the first is the title.
  double duration_s = 3;         ///< unit: s (video time)
  double fade_s = 0.5;           ///< Fade in and out. unit: s
  double size = 0.08;            ///< Title height as a fraction of the frame height. unit: 1
  Color color = Color(0.95, 0.95, 0.95);
  Origin origin;
};

/// Text at the bottom of the clip over a time range, fading in and out.
struct Caption {
  std::string text;
  double from_s = 0;             ///< Video time from the clip's first frame (after the cards). unit: s
  double to_s = 0;               ///< unit: s
  double fade_s = 0.3;           ///< unit: s
  double size = 0.05;            ///< Text height as a fraction of the frame height. unit: 1
  Color color = Color(1, 1, 1);
  Origin origin;
};

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
  std::vector<View> views;  ///< Split screen; empty: one view of every organ with `camera`.
  Output output;
  std::vector<Card> cards;         ///< Shown in order before the clip.
  std::vector<Caption> captions;
  Overlay overlay;
};

}  // namespace systole::scene
