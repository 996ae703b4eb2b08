#pragma once
// A 12-lead ECG sheet drawn as a clinician prints it: pink millimetre paper (minor lines
// every 1 mm, darker major lines every 5 mm) at the standard 25 mm/s and 10 mm/mV; three
// rows of four 2.5-s columns (I aVR V1 V4 / II aVL V2 V5 / III aVF V3 V6), column c showing
// [c * 2.5, (c + 1) * 2.5) s of one 10-s window, and a lead II rhythm strip over all 10 s
// below them; a 1-mV, 200-ms calibration pulse at the start of every row; a caption with
// the window, speed and gain. The paper is scaled, never stretched, so the whole sheet fits
// its box: one millimetre is the same number of pixels across and down.
//
// As on paper, a deflection taller than its row runs into the neighbouring row rather than
// being cut at the row's edge: its voltage is what a reader measures (voltage criteria of
// hypertrophy). It is cut only at the edge of the grid, so the sheet never draws outside
// its box.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "common/image.h"
#include "overlay/layout.h"

namespace systole::overlay {

constexpr double kEcgPaperSpeed_mm_per_s = 25;  ///< unit: mm/s
constexpr double kEcgGain_mm_per_mV = 10;       ///< unit: mm/mV
constexpr double kEcgWindow_s = 10;             ///< The time a sheet shows. unit: s
constexpr double kEcgColumn_s = 2.5;            ///< The time one column of the 3x4 leads shows. unit: s
constexpr int kEcgRows = 4;                     ///< Three rows of leads and the rhythm strip.

/// A recording of some of the 12 standard leads, every lead sampled at the same instants.
struct EcgSheet {
  std::string title;           ///< Top left of the sheet; empty: none.
  double rate_hz = 500;        ///< Samples per second of every lead. unit: Hz
  double start_s = 0;          ///< Time of every lead's sample 0. unit: s
  std::vector<std::string> leads;       ///< Names among I II III aVR aVL aVF V1..V6, each once.
  std::vector<std::vector<double>> mv;  ///< mv[i][k]: lead leads[i] at start_s + k / rate_hz; NaN: a gap. unit: mV
};

/// Where a sheet drawn in a box puts things. x grows right, y down. unit: px
struct EcgSheetLayout {
  double px_per_mm = 0;          ///< unit: px/mm
  double grid_x = 0, grid_y = 0;  ///< Top-left corner of the grid (a major line). unit: px
  double grid_width = 0, grid_height = 0;  ///< 260 mm x 120 mm. unit: px
  /// x of the window's start: right of the 10-mm calibration lead-in. unit: px
  double trace_x = 0;
  /// 0 mV of the rows: 0-2 the 3x4 leads, 3 the rhythm strip. unit: px
  std::array<double, kEcgRows> baseline_y{};
  double row_height = 0;  ///< 30 mm. unit: px

  /// Top of row `row` (0-3). unit: px
  double row_top(int row) const { return grid_y + row * row_height; }
  /// x of the time `t_s` after the window's start, at 25 mm/s. unit: px
  double x_at(double t_s) const { return trace_x + t_s * kEcgPaperSpeed_mm_per_s * px_per_mm; }
  /// y of `mv` in row `row`, at 10 mm/mV. unit: px
  double y_at(int row, double mv) const { return baseline_y[row] - mv * kEcgGain_mm_per_mV * px_per_mm; }
};

/// The geometry of a sheet drawn in `box`: the largest millimetre that fits the sheet
/// (grid, caption and margins: 268 mm x 135 mm), the sheet centred in the box.
EcgSheetLayout ecg_sheet_layout(const Rect& box);

/// Start of the 10 s shown at `now_s`: pages of 10 s from sheet.start_s, the page that
/// contains `now_s`, a page's end belonging to it (at 10 s the sheet still shows 0-10 s).
/// Before start_s, the first page. unit: s
double ecg_sheet_window_start_s(const EcgSheet& sheet, double now_s);

/// Draws the sheet over all of `box` (opaque paper) showing the page that contains `now_s`,
/// samples after `known_until_s` left out, as an ECG machine writes while it records: a
/// video passes its current time for both. Throws Error(kDataError) when the sheet is not
/// valid (an unknown or repeated lead name, as many sample lists as names, a positive
/// finite rate, finite start_s and now_s, a known_until_s that is not NaN).
void draw_ecg_sheet(Image& image, const Rect& box, const EcgSheet& sheet, plot::Font& font, double now_s,
                    double known_until_s = std::numeric_limits<double>::infinity());

/// The sheet alone, `width_px` wide and as tall as its aspect (268:135) gives, showing the
/// last 10 s of the recording (from start_s when it is shorter), every sample known.
/// Throws Error(kDataError) for an invalid sheet and Error(kUsage) for a width outside
/// 268 (1 px per mm) .. 16384 px.
Image ecg_sheet_still(const EcgSheet& sheet, plot::Font& font, int width_px);

}  // namespace systole::overlay
