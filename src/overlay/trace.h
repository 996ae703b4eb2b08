#pragma once
// A live trace inset: a small plot of one signal over time with a cursor at the current
// time, drawn as a bedside monitor sweeps: the time axis is a window of `window_s`; the
// cursor runs left to right across it; left of the cursor is this sweep, right of it
// (after a short erased gap) what the previous sweep drew. A window as long as the clip
// shows the whole clip at once, like a Wiggers diagram: signals known in advance (drive
// activation, the synthetic ECG) are drawn complete, the part ahead of the cursor dimmed;
// a signal known only as it is simulated (volume) grows behind the cursor.

#include <limits>
#include <string>
#include <vector>

#include "common/image.h"
#include "overlay/layout.h"

namespace systole::overlay {

/// A signal sampled evenly from t = 0; NaN where it is unknown.
struct Trace {
  std::string title;        ///< "ECG (synthetic)", "volume: heart".
  std::string unit;         ///< When not empty, the current value is shown with it: "mL".
  Rgb color{120, 230, 150};
  double sample_dt_s = 1.0 / 500;  ///< unit: s
  std::vector<double> values;      ///< values[i] at t = i * sample_dt_s.
  /// Samples after this time are not known yet (a simulated signal: the current time). unit: s
  double known_until_s = std::numeric_limits<double>::infinity();
  double window_s = 3;  ///< Width of the sweep; >= clip_s: the whole clip. unit: s
  double clip_s = 10;   ///< unit: s
  double min = 0, max = 0;  ///< The value range shown; min >= max: fitted to the known values.
};

/// The value at `t_s`, linear between samples; NaN outside the samples or where unknown.
double sample(const Trace& trace, double t_s);

/// Where the plot area of an inset in `box` is, for `font` at the inset's text size. unit: px
Rect trace_plot_area(const Rect& box, const plot::Font& font);
/// The cursor's x at time `now_s` in a plot area. unit: px
double cursor_x(const Rect& plot, const Trace& trace, double now_s);

/// Draws the inset in `box` at time `now_s`.
void draw_trace(Image& image, const Rect& box, const Trace& trace, double now_s, plot::Font& font,
                const Style& style = {});

/// A synthetic ECG (unit: mV, roughly lead II) with one QRS-T complex per beat: the R peak at
/// each of `r_times_s`, T after a QT interval that scales with the square root of the RR
/// interval (Bazett). P waves peak at `p_times_s`, or, when it is null, 160 ms before each
/// R (a sinus rhythm's PR interval); an empty list draws none (atrial fibrillation). A
/// teaching marker of the beats, not a model of the heart's electrical activity.
double ecg_value(double t_s, const std::vector<double>& r_times_s, const std::vector<double>* p_times_s = nullptr);

}  // namespace systole::overlay
