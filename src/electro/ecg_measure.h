#pragma once
// What a cardiologist reads off one beat of a 12-lead ECG: the intervals, the frontal axis,
// the precordial R/S transition and each lead's deflections. Measured on the computed
// leads as automated ECG programs measure a beat: the waves' edges on the leads' combined
// amplitude and slope (a global measure over the leads, as the CSE study's programs agree
// on; Willems et al. 1985, "Assessment of the performance of electrocardiographic computer
// programs with the use of a reference data base", Circulation 71:523).

#include <array>
#include <string>

#include "electro/ecg.h"

namespace systole::electro {

/// One lead's waves in a beat. unit: mV, mV s
struct LeadWaves {
  double q = 0;         ///< The QRS's first deflection when it is negative (its depth), else 0.
  double r = 0;         ///< The QRS's highest point above the baseline.
  double s = 0;         ///< Its lowest point below it (a positive depth).
  double r_prime = 0;   ///< A second positive peak after a dip (an R'), else 0.
  double qrs_area = 0;  ///< Net area of the QRS. unit: mV s
  double t = 0;         ///< The T wave's largest deflection, with its sign.
  int r_peaks = 0;      ///< Local maxima of the QRS above a fifth of its R: 2 for a notched or an rsR' complex.
  /// How long the positive wave holding the R lasts, and the deepest negative wave after it
  /// (the terminal S; in a QS complex the whole), each from where it leaves the baseline (5 %
  /// of the QRS's largest deflection) to where it returns, within the QRS. unit: s
  double r_duration_s = 0, s_duration_s = 0;
  /// QRS onset to the last R peak: the R peak time (the intrinsicoid deflection). unit: s
  double r_peak_time_s = 0;
};

struct BeatMeasures {
  double p_onset_s = 0, qrs_onset_s = 0, qrs_offset_s = 0, t_end_s = 0;  ///< On the ECG's clock. unit: s
  double pr_s = 0, qrs_s = 0, qt_s = 0;  ///< unit: s
  double qtc_s = 0;     ///< QT / sqrt(RR / 1 s) (Bazett 1920). unit: s
  double axis_deg = 0;  ///< Frontal QRS axis from the net areas of I and aVF. unit: deg
  /// The first precordial lead (1..6 for V1..V6) whose R is at least its S; 7: none.
  int transition = 7;
  std::array<LeadWaves, 12> leads{};  ///< standard_leads() order.
};

/// Measures the beat whose P wave starts in [from_s, to_s) (to_s: the next beat's start);
/// `cycle_s` is its RR interval for the QTc. Throws common/error.h's Error when the window
/// holds no QRS complex.
BeatMeasures measure_beat(const Ecg& ecg, double from_s, double to_s, double cycle_s);

/// The lead's index in standard_leads() ("V5" -> 10), or -1.
int lead_index(const std::string& name);

}  // namespace systole::electro
