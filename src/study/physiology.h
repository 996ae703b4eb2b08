#pragma once
// `systole validate --physiology`: the figures a cardiologist measures, taken from the
// simulated anatomical heart (mesh/anatomy.h) over one beat after the body has settled:
// chamber volumes from the closed cavity linings, the ejection fraction, base-to-apex
// shortening and wall thickening from landmarks, left-ventricular twist from the rotation
// of an apical and a basal ring, and when each valve opens and closes. docs/anatomy.md
// gives the normal ranges and their sources.

#include <limits>
#include <string>
#include <vector>

#include "electro/ecg_measure.h"
#include "scene/scene.h"

namespace systole::study {

/// A normal range and where it comes from (docs/anatomy.md).
struct NormalRange {
  double low = 0, high = 0;
  const char* source = "";
  bool holds(double value) const { return value >= low && value <= high; }
};

/// Left ventricle of a normal adult heart at rest (Lang et al. 2015; Sengupta et al. 2008;
/// Rademakers et al. 1992; docs/anatomy.md). The volumes are the "roughly 120 -> 50 ml".
inline const NormalRange kEndDiastolicVolume{100, 150, "Lang 2015, table 1 (LV EDV, men 62-150 ml)"};
inline const NormalRange kEndSystolicVolume{35, 65, "Lang 2015, table 1 (LV ESV, men 21-61 ml)"};
inline const NormalRange kEjectionFraction{55, 70, "Lang 2015 (LVEF normal 52-72 %)"};
inline const NormalRange kLongAxisShortening{10, 20, "Rogers 1991; Henein & Gibson 1999 (long axis 10-20 %)"};
inline const NormalRange kWallThickening{30, 50, "Sheehan 1986; Azhari 1993 (systolic wall thickening 30-50 %)"};
inline const NormalRange kTwist{10, 20, "Sengupta 2008; Notomi 2005 (peak LV twist 10-20 deg)"};
/// Ejection (aortic valve open) as a share of the beat at 60-80 bpm: 270-330 ms of 750-1000 ms.
inline const NormalRange kEjectionShare{25, 40, "Weissler 1968; Guyton & Hall ch. 9 (ejection 0.27-0.3 s)"};
/// Isovolumic relaxation: the aortic valve's closure to the mitral valve's opening, when the
/// ventricle relaxes with both shut. Normal means by age 50-87 ms, +-2 SD 32-101 ms.
inline const NormalRange kIsovolumicRelaxation{50, 100, "Nagueh et al. 2009, J Am Soc Echocardiogr 22:107 (IVRT by age)"};

/// The resting 12-lead ECG of a normal adult (docs/electrophysiology.md): the AHA/ACCF/HRS
/// recommendations for the standardization and interpretation of the electrocardiogram
/// (Surawicz et al. 2009, Circulation 119:e235; Rautaharju et al. 2009, Circulation 119:e241).
inline const NormalRange kPrInterval{120, 200, "Surawicz 2009 (PR 120-200 ms)"};
inline const NormalRange kQrsDuration{80, 110, "Surawicz 2009 (QRS under 110 ms; 120 and more a bundle branch block)"};
inline const NormalRange kQtc{350, 450, "Rautaharju 2009 (QTc by Bazett, 350-450 ms)"};
inline const NormalRange kQrsAxis{-30, 90, "Surawicz 2009 (frontal QRS axis -30 to +90 deg)"};
inline const NormalRange kTransition{2, 4, "Surawicz 2009 (precordial R/S transition V2-V4)"};
/// QRS onset to the mitral valve's closure: the Q-M1 interval of phonocardiography.
inline const NormalRange kElectromechanicalDelay{20, 80, "Leatham 1954, Lancet 267:607 (Q to the mitral first sound, 20-80 ms)"};

struct ChamberVolume {
  std::string name;          ///< "left_ventricle", ...
  double largest_ml = 0;     ///< unit: ml
  double smallest_ml = 0;    ///< unit: ml
  double emptied_pct() const { return largest_ml > 0 ? 100 * (largest_ml - smallest_ml) / largest_ml : 0; }
};

/// Below this a segment's systolic thickening is negligible: the segment is akinetic, as a
/// scar is (Lang et al. 2015, "Regional LV function": akinesis is absent or negligible
/// thickening; 10 % is our threshold for negligible).
inline constexpr double kAkineticThickeningPct = 10;

/// The septum's (AHA 8, 9) and the lateral wall's (11, 12) times to peak thickening this far
/// apart or more: a dyssynchronous left ventricle, as left bundle branch block makes it. Bax
/// et al. 2003 (Am J Cardiol 92:1238) took a 60-ms septal-to-lateral delay as dyssynchrony.
inline constexpr double kDyssynchronyDelayMs = 60;

/// Systolic thickening of one mid-ventricular segment (AHA 7-12, mesh/anatomy.h).
struct SegmentThickening {
  int segment = 0;           ///< 7 anterior ... 12 anterolateral.
  const char* name = "";
  double thickening_pct = 0;
  /// When the segment is thickest in the beat, after the ventricles' activation (to the
  /// solver's step, or the frame without blood). unit: ms
  double peak_ms = std::numeric_limits<double>::quiet_NaN();
  bool akinetic() const { return thickening_pct < kAkineticThickeningPct; }
};

struct ValveEvent {
  std::string valve;  ///< "mitral_valve"
  bool opens = true;  ///< Opens, or closes.
  double after_activation_ms = 0;  ///< After the left ventricle's activation begins. unit: ms
};

struct PhysiologyReport {
  std::string scene, organ;
  double beat_s = 0;                 ///< unit: s
  double measured_from_s = 0;        ///< The measured beat starts here (the ventricles' activation). unit: s
  double frame_s = 0;                ///< Sampling (the scene's frames). unit: s
  std::vector<ChamberVolume> chambers;
  double end_diastolic_ml = 0, end_systolic_ml = 0, ejection_fraction_pct = 0;  ///< Left ventricle.
  /// After activation: the first frame after the aortic valve closes where blood times the
  /// valves, else the left ventricle's smallest. unit: ms
  double end_systole_ms = 0;
  double long_axis_shortening_pct = 0;
  double wall_thickening_pct = 0;
  std::vector<SegmentThickening> segments;  ///< Mid-ventricular, AHA order 7-12.
  /// The lateral wall's time to peak thickening (segments 11, 12) less the septum's (8, 9).
  double septal_lateral_delay_ms = std::numeric_limits<double>::quiet_NaN();
  double apical_rotation_deg = 0, basal_rotation_deg = 0, twist_deg = 0;  ///< At peak twist; anticlockwise seen from the apex positive.
  double muscle_volume_change_pct = 0;  ///< Largest change of the myocardium's volume over the beat.
  std::vector<ValveEvent> valve_events;
  double ejection_pct = 0;           ///< Share of the beat the aortic valve is open. unit: %
  /// The aortic valve's closure to the mitral valve's next opening, to the frame (with
  /// blood, to the solver's step; NaN when either is missing). unit: ms
  double isovolumic_relaxation_ms = std::numeric_limits<double>::quiet_NaN();
  /// With electrophysiology, the measured beat's computed ECG (electro/ecg_measure.h); the
  /// electromechanical delay is its QRS onset to the mitral valve's closure (NaN without).
  bool has_ecg = false;
  electro::BeatMeasures ecg;
  double electromechanical_delay_ms = std::numeric_limits<double>::quiet_NaN();
  /// Names of the figures outside their normal range (empty: a normal heart).
  std::vector<std::string> outside_normal() const;
};

/// Runs the scene's first organ with an anatomy (the generated heart) for `settle_beats`
/// beats of its left ventricle's drive, then measures the next. Throws Error(kUsage) when
/// no organ has an anatomy or no region named left_ventricle has a periodic drive, and
/// Error(kDiverged) as the world does.
PhysiologyReport measure_physiology(const scene::Scene& scene, int settle_beats = 2);

/// The report as `validate --physiology` prints it.
std::string physiology_text(const PhysiologyReport& report);

}  // namespace systole::study
