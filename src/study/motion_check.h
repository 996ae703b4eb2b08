#pragma once
// `systole motion`: is the organ's motion what a beating organ's is? It runs the scene and
// checks what a viewer would see go wrong with a mesh the body does not suit: every
// periodically driven region repeats its beat (a body that slowly crumples or drifts does
// not), no part of a multi-part surface passes through another (study/part_crossing.h), and
// a generated anatomy keeps its linings inside its walls (study/lining_watch.h; with
// MotionOptions::outside_view, also as an outside view sees them, study/lining_view.h).

#include <string>
#include <vector>

#include "scene/scene.h"
#include "study/part_crossing.h"

namespace systole::study {

/// A beat may differ from the one before by this share of its peak-to-peak excursion. unit: %
inline constexpr double kBeatToBeatTolerancePct = 2.0;
/// A vertex may end up this far on the other side of a part it was beside at rest (a tenth
/// of a millimetre: below what a frame shows of an organ). unit: m
inline constexpr double kCrossingTolerance_m = 1e-4;

struct MotionOptions {
  double duration_s = 0;   ///< Organ time simulated; 0: the scene's output duration. unit: s
  double band_m = 0.001;   ///< How near another part a vertex is compared (part_crossing.h). unit: m
  /// Beats left out as the body leaves its rest shape: one for most bodies; a lightly damped
  /// one (the anatomical heart, 1 ms) still rings out of it through the second.
  int settle_beats = 1;
  /// Also draw the scene's views uncut, opaque and coloured by region at every frame, and
  /// count the lining pixels they show (study/lining_view.h).
  bool outside_view = false;
};

/// One periodically driven region's beats, compared each with the one before; the first
/// beats, out of the rest shape (MotionOptions::settle_beats), are left out.
struct RegionBeats {
  std::string name;            ///< "heart.left_ventricle"
  double period_s = 0;         ///< unit: s
  int beats = 0;               ///< Whole beats compared (after the settling ones).
  double peak_to_peak_m = 0;   ///< Of its radial excursion in the last beat. unit: m
  double worst_change_pct = 0; ///< RMS difference from the beat before, % of that beat's peak to peak. unit: %
  int worst_beat = 0;          ///< Which beat (the first is 0) differed most from its predecessor.
};

struct OrganParts {
  std::string organ;
  std::vector<std::string> parts;  ///< The parts checked against each other.
  std::size_t pairs_compared = 0;
  PartCrossingWatch::Crossing worst;
};

/// A generated anatomy's linings against its walls' outside, frame by frame.
struct OrganLinings {
  std::string organ;
  int lining_vertices = 0;  ///< Watched (mesh::lining_vertices).
  int frames = 0;
  int frames_outside = 0;   ///< Frames with a lining vertex outside the epicardium.
  int worst_outside = 0;    ///< The most lining vertices outside in one frame.
  int worst_frame = -1;
  std::string worst_cavity; ///< The cavity a vertex outside at the worst frame lines.
};

/// The lining pixels of the outside view (MotionOptions::outside_view), frame by frame.
struct OutsideView {
  bool drawn = false;
  int width = 0, height = 0;  ///< unit: px
  int frames = 0;
  int frames_with_pixels = 0;
  int worst_pixels = 0;       ///< The most lining pixels in one frame.
  int worst_frame = -1;
};

struct MotionReport {
  std::string scene;
  double duration_s = 0;      ///< unit: s
  int frames = 0;
  double band_m = 0;          ///< Crossings are measured up to this depth (MotionOptions). unit: m
  int settle_beats = 1;       ///< Beats left out (MotionOptions).
  std::vector<std::string> bodies;  ///< Per organ: its body and why.
  std::vector<RegionBeats> regions;
  std::vector<OrganParts> organs;
  /// Organs whose parts are not checked: a generated anatomy's parts are labels on one
  /// welded wall (a septum is part of both ventricles' walls), not surfaces that could pass
  /// through each other; its moving valve leaflets sit on the walls they hinge from. Its
  /// linings are checked instead (`linings`).
  std::vector<std::string> anatomies;
  std::vector<OrganLinings> linings;
  OutsideView view;

  bool periodic() const;      ///< Every region repeats its beat within the tolerance.
  bool parts_kept() const;    ///< No part passed through another beyond the tolerance.
  /// No lining vertex left its wall's outside, and the outside view (if drawn) showed no lining.
  bool linings_inside() const;
};

/// Runs the scene for the duration, frame by frame. Throws Error(kDiverged) when the body
/// blows up or crumples (world::advance_to_frame), Error(kUsage) when it is too short to
/// compare two beats of any region and has no parts to check.
MotionReport check_motion(const scene::Scene& scene, const MotionOptions& options);

/// The report as `systole motion` prints it.
std::string motion_text(const MotionReport& report);

}  // namespace systole::study
