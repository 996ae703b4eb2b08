#pragma once
// The video file: size, rate, duration, loop, container and encoder settings.

#include <string>

#include "scene/origin.h"

namespace systole::scene {

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
  /// Draw the captions into the frames; they are also a subtitle track and a .vtt file.
  bool burn_captions = true;
  Color background = Color(0.06, 0.07, 0.09);

  int frame_count() const;  ///< Frames of the clip (title cards not counted): round(duration * fps * slow_motion).
  /// Organ time between two frames: 1 / (fps * slow_motion), or for a loop duration /
  /// frame_count() exactly (the playback rate then differs by less than 1 / (2 frames)). unit: s
  double frame_period_s() const;
  /// The organ time clip frame k shows: (start_frame + k) * frame_period_s(), after a
  /// loop's settling frames, slowed by slow_motion. unit: s
  double organ_time_s(int frame) const;
};

}  // namespace systole::scene
