#pragma once
// The soundtrack a scene asks for (docs/sound.md): heart sounds timed by the simulated
// ventricles, breath sounds following a lung's simulated volume flow, and a metronome
// click. Off unless the scene has `audio:`.

#include <string>
#include <vector>

#include "scene/origin.h"

namespace systole::scene {

/// Where the stethoscope rests: it weights the heart sounds' components as auscultation
/// does (Bickley, "Bates' Guide to Physical Examination", ch. 9): S1 is loudest at the apex,
/// S2 at the base (second intercostal spaces).
enum class Stethoscope { kApex, kBase };

/// A murmur's loudness over its window.
enum class MurmurShape {
  kDiamond,      ///< Crescendo-decrescendo (ejection murmur, e.g. aortic stenosis).
  kPlateau,      ///< Even loudness (holosystolic, e.g. mitral regurgitation).
  kDecrescendo,  ///< Loudest at the start (e.g. aortic regurgitation, diastolic).
  kCrescendo,    ///< Loudest at the end (e.g. mitral stenosis's presystolic accentuation).
};

/// Which part of the cycle a murmur fills.
enum class MurmurPhase {
  kSystolic,   ///< From S1 to S2.
  kDiastolic,  ///< From S2 to the next S1.
};

/// One heart-sound component.
struct HeartTone {
  bool enabled = true;
  double level_db = 0;  ///< Loudness relative to the component's model. unit: dB
};

struct Murmur {
  bool enabled = false;
  MurmurShape shape = MurmurShape::kDiamond;
  MurmurPhase phase = MurmurPhase::kSystolic;
  double from = 0.1;           ///< Start as a fraction of the phase. unit: 1
  double to = 0.9;             ///< End as a fraction of the phase. unit: 1
  double pitch_hz = 180;       ///< Centre of the noise band. unit: Hz
  double level_db = -12;       ///< unit: dB
  Origin origin;
};

struct HeartAudio {
  bool enabled = false;
  std::string organ;                 ///< Empty: the first organ with a ventricular region.
  std::vector<std::string> regions;  ///< Ventricular regions; empty: every region whose name has "ventric".
  Stethoscope stethoscope = Stethoscope::kApex;
  HeartTone s1, s2;
  HeartTone s3{false, -6};           ///< Off unless the scene names it.
  Murmur murmur;
  Origin origin;
};

struct BreathAudio {
  bool enabled = false;
  std::string organ;      ///< Empty: the first organ whose body has a volume drive.
  double level_db = -6;   ///< unit: dB
  Origin origin;
};

struct ClickAudio {
  bool enabled = false;
  double rate_hz = 1;     ///< unit: Hz (organ time: slowed with the clip)
  double start_s = 0;     ///< First click, organ time from the clip's first frame. unit: s
  double level_db = -12;  ///< unit: dB
  Origin origin;
};

struct Audio {
  bool enabled = false;
  double level_db = -3;   ///< Master gain. unit: dB
  HeartAudio heart;
  BreathAudio breath;
  ClickAudio click;
  Origin origin;
};

}  // namespace systole::scene
