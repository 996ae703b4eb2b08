#pragma once
// What a scene adds for teaching: split-screen views, title cards, captions and overlays.

#include <string>
#include <vector>

#include "scene/organ.h"
#include "scene/origin.h"
#include "scene/world.h"

namespace systole::scene {

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

/// A chapter mark of the video (besides one per title card), for players' chapter menus.
struct Chapter {
  std::string title;
  double at_s = 0;               ///< Video time from the clip's first frame (after the cards). unit: s
  Origin origin;
};

// Teaching overlays drawn on each frame (src/overlay/, docs/teaching-visuals.md). Sizes are
// pixels of a 720-line frame, scaled with output.height.

enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

struct LabelsOverlay {
  bool enabled = false;
  std::string organ;                 ///< Empty: every organ.
  std::vector<std::string> regions;  ///< Empty: every region (`all`).
  /// Title of the view labelled; empty: each organ in the first view that shows it. In a
  /// cut view a region is anchored on what the cut keeps of it, so inner parts can be named.
  std::string view;
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
  kEcg,         ///< A computed lead (an organ with electrophysiology), else a synthetic P-QRS-T at each beat of a region's drive.
};

struct TraceOverlay {
  TraceSignal signal = TraceSignal::kVolume;
  std::string organ;                 ///< Empty: the first organ.
  std::string region;                ///< kActivation, kEcg: the region whose drive is shown (kEcg: the ventricles').
  std::string atria;                 ///< kEcg: a region whose beats give the P waves; empty: 160 ms before each R.
  std::string lead = "II";           ///< kEcg of an organ with electrophysiology: the computed lead shown.
  std::string chamber;               ///< kVolume: a cavity of a generated anatomy; empty: the organ's enclosed volume.
  Corner position = Corner::kBottomRight;
  int width_px = 360, height_px = 110;  ///< unit: px at 720 lines
  double window_s = 3;               ///< Sweep width; 0: the whole clip. unit: s
  Origin origin;
};

/// The organ's computed 12-lead ECG as a sheet of ECG paper (overlay/ecg_sheet.h), written
/// up to the frame's time as an ECG machine writes while it records.
struct EcgSheetOverlay {
  bool enabled = false;
  std::string organ;                 ///< Empty: the first organ.
  Corner position = Corner::kBottomRight;
  int width_px = 520;                ///< The height follows the sheet's 268:135. unit: px at 720 lines
  Origin origin;
};

struct Overlay {
  std::string title;                 ///< Across the top; empty: none.
  int title_size_px = 26;            ///< unit: px at 720 lines
  LabelsOverlay labels;
  LegendOverlay legend;
  std::vector<TraceOverlay> traces;  ///< Insets; several in one corner stack.
  EcgSheetOverlay ecg_sheet;

  bool empty() const { return title.empty() && !labels.enabled && !legend.enabled && traces.empty() && !ecg_sheet.enabled; }
};

}  // namespace systole::scene
