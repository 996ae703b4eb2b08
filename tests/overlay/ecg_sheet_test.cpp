// The 12-lead ECG sheet, read back from its pixels as a clinician reads paper: the major
// lines are 5 mm apart; a 1-mV step rises 10 mm at the x that 25 mm/s gives its time; each
// cell of the 3x4 layout shows its own lead over its own 2.5 s; the rhythm strip runs the
// whole 10 s; a missing lead leaves a labelled blank cell; nothing is written after the
// known time; the calibration pulse is 1 mV by 200 ms; tall deflections overlap the next
// row but never leave the grid; invalid sheets are refused.
//
// The standard (25 mm/s, 10 mm/mV) is written out here rather than taken from the code's
// constants, so a wrong constant fails these tests instead of moving their expectations.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/error.h"
#include "overlay/ecg_sheet.h"

namespace systole::overlay {
namespace {

constexpr double kMmPerS = 25;   // Paper speed. unit: mm/s
constexpr double kMmPerMv = 10;  // Gain. unit: mm/mV
constexpr double kRateHz = 500;
// 268 mm x 135 mm (grid, caption, margins) at exactly 5 px per mm.
const Rect kBox{0, 0, 1340, 675};
const std::array<std::array<const char*, 4>, 3> kLeadAt = {
    {{"I", "aVR", "V1", "V4"}, {"II", "aVL", "V2", "V5"}, {"III", "aVF", "V3", "V6"}}};

/// Twelve flat leads (0 mV) over `seconds` from `start_s`.
EcgSheet flat_sheet(double seconds = 10, double start_s = 0) {
  EcgSheet sheet;
  sheet.rate_hz = kRateHz;
  sheet.start_s = start_s;
  for (const auto& row : kLeadAt) {
    for (const char* name : row) {
      sheet.leads.push_back(name);
      sheet.mv.emplace_back(static_cast<std::size_t>(seconds * kRateHz), 0.0);
    }
  }
  return sheet;
}

/// Sets lead `name` to `mv` on [from_s, to_s): a rectangular pulse.
void add_pulse(EcgSheet& sheet, const std::string& name, double from_s, double to_s, double mv) {
  for (std::size_t i = 0; i < sheet.leads.size(); ++i) {
    if (sheet.leads[i] != name) continue;
    for (std::size_t k = 0; k < sheet.mv[i].size(); ++k) {
      const double t = sheet.start_s + double(k) / sheet.rate_hz;
      if (t >= from_s && t < to_s) sheet.mv[i][k] = mv;
    }
  }
}

Image draw(const EcgSheet& sheet, double now_s, double known_until_s = std::numeric_limits<double>::infinity()) {
  Image image(kBox.width, kBox.height);
  plot::Font font;
  draw_ecg_sheet(image, kBox, sheet, font, now_s, known_until_s);
  return image;
}

/// Ink: the trace, labels and ticks. The grid's darkest red (and paper) has a bright red channel.
bool inked(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] < 150 && p[1] < 150 && p[2] < 150;
}

/// Inked pixels in [x0, x1) x [y0, y1). unit: px
int ink_in(const Image& image, double x0, double x1, double y0, double y1) {
  int n = 0;
  for (int y = int(std::lround(y0)); y < int(std::lround(y1)); ++y) {
    for (int x = int(std::lround(x0)); x < int(std::lround(x1)); ++x) n += inked(image, x, y);
  }
  return n;
}

/// Whether column `x` is inked within `tolerance` px of `y`.
bool ink_near(const Image& image, double x, double y, int tolerance = 1) {
  for (int dy = -tolerance; dy <= tolerance; ++dy) {
    if (inked(image, int(x), int(std::floor(y)) + dy)) return true;
  }
  return false;
}

/// The highest inked pixel of column `x` in [y0, y1); -1: none.
int topmost_ink(const Image& image, int x, double y0, double y1) {
  for (int y = int(std::lround(y0)); y < int(std::lround(y1)); ++y) {
    if (inked(image, x, y)) return y;
  }
  return -1;
}

/// The x of time `t_s` of the window, by the standard. unit: px
double x_of(const EcgSheetLayout& l, double t_s) { return l.trace_x + t_s * kMmPerS * l.px_per_mm; }
/// The y of `mv` in row `row`, by the standard. unit: px
double y_of(const EcgSheetLayout& l, int row, double mv) { return l.baseline_y[row] - mv * kMmPerMv * l.px_per_mm; }
/// A row's band below its label (1.5 mm down, about 3 mm tall): where its trace runs. unit: px
double band_top(const EcgSheetLayout& l, int row) { return l.row_top(row) + 6 * l.px_per_mm; }
double band_bottom(const EcgSheetLayout& l, int row) { return l.row_top(row) + l.row_height; }

TEST(EcgSheet, LayoutFitsTheWholeSheetInTheBoxWithSquareMillimetres) {
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  EXPECT_DOUBLE_EQ(l.px_per_mm, 5.0);
  // 10 mm of calibration lead-in and 10 s at 25 mm/s; four rows of 30 mm.
  EXPECT_DOUBLE_EQ(l.grid_width, (10 + 10 * kMmPerS) * 5);
  EXPECT_DOUBLE_EQ(l.trace_x - l.grid_x, 10 * 5);
  EXPECT_DOUBLE_EQ(l.row_height, 30 * 5);
  for (int row = 1; row < kEcgRows; ++row) EXPECT_DOUBLE_EQ(l.baseline_y[row] - l.baseline_y[row - 1], l.row_height);
  EXPECT_GE(l.grid_x, kBox.x);
  EXPECT_GT(l.grid_y, kBox.y);  // The caption sits above the grid.
  EXPECT_LE(l.grid_x + l.grid_width, kBox.right());
  EXPECT_LE(l.grid_y + l.grid_height, kBox.bottom());

  // A wider box keeps the millimetre square (height limits it) and centres the sheet.
  const Rect wide{100, 40, 2400, 675};
  const EcgSheetLayout w = ecg_sheet_layout(wide);
  EXPECT_DOUBLE_EQ(w.px_per_mm, 5.0);
  EXPECT_NEAR(w.grid_x + 0.5 * w.grid_width, wide.x + 0.5 * wide.width, 1.0);
  EXPECT_DOUBLE_EQ(w.grid_y - wide.y, l.grid_y - kBox.y);
}

TEST(EcgSheet, GridMajorLinesAreFiveMillimetresApartAndMinorLinesOne) {
  EcgSheet empty;  // No leads: only paper, labels and calibration pulses.
  const Image image = draw(empty, 0);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  // A pixel row between horizontal lines, clear of labels, ticks and calibration: 26.5 mm into row 1.
  const int y = int(l.row_top(1) + 26.5 * l.px_per_mm);
  std::vector<int> major, any_line;
  for (int x = int(l.grid_x); x <= int(l.grid_x + l.grid_width); ++x) {
    const std::uint8_t* p = image.pixel(x, y);
    ASSERT_GT(p[0], 200) << "no ink expected at x " << x;  // Every grid colour is red-dominant.
    if (p[1] < 160) major.push_back(x);
    if (p[1] < 230) any_line.push_back(x);
  }
  ASSERT_EQ(major.size(), 260u / 5 + 1);  // Both edges of the 260-mm grid are major lines.
  for (std::size_t i = 1; i < major.size(); ++i) EXPECT_NEAR(major[i] - major[i - 1], 5 * l.px_per_mm, 1.0) << i;
  ASSERT_EQ(any_line.size(), 260u + 1);
  for (std::size_t i = 1; i < any_line.size(); ++i) EXPECT_NEAR(any_line[i] - any_line[i - 1], l.px_per_mm, 1.0) << i;
  // Major lines are darker than minor ones.
  const std::uint8_t* minor_px = image.pixel(any_line[1], y);
  const std::uint8_t* major_px = image.pixel(major[1], y);
  EXPECT_LT(major_px[1] + 40, minor_px[1]);
}

TEST(EcgSheet, OneMillivoltRisesTenMillimetresAtTheXOfTwentyFiveMillimetresPerSecond) {
  EcgSheet sheet = flat_sheet();
  add_pulse(sheet, "II", 0.5, 0.7, 1.0);
  add_pulse(sheet, "II", 8.5, 8.7, 1.0);
  const Image image = draw(sheet, 10);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  const int row = 3;  // The rhythm strip: lead II over all 10 s.
  // Flat before the pulse: ink at the baseline and nowhere above it.
  EXPECT_NEAR(topmost_ink(image, int(x_of(l, 0.3)), band_top(l, row), band_bottom(l, row)), l.baseline_y[row], 1.5);
  // On the pulse: the trace is 10 mm above the baseline, and the baseline is bare.
  const int top = topmost_ink(image, int(x_of(l, 0.6)), band_top(l, row), band_bottom(l, row));
  EXPECT_NEAR(top, y_of(l, row, 1.0), 1.5);
  EXPECT_FALSE(ink_near(image, x_of(l, 0.6), l.baseline_y[row] + 1, 2));
  // The rising edges: the first columns inked at 1 mV, at 0.5 s and 8.5 s by 25 mm/s.
  std::vector<int> edges;
  bool was = false;
  for (int x = int(l.trace_x); x < int(l.grid_x + l.grid_width); ++x) {
    const bool is = ink_near(image, x, y_of(l, row, 1.0));
    if (is && !was) edges.push_back(x);
    was = is;
  }
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_NEAR(edges[0], x_of(l, 0.5), 2.0);
  EXPECT_NEAR(edges[1], x_of(l, 8.5), 2.0);
  EXPECT_NEAR(edges[1] - edges[0], 8 * kMmPerS * 5, 1.0);
}

TEST(EcgSheet, EachCellShowsItsLeadDuringItsColumnsSliceOfTheWindow) {
  // Lead (row, column) pulses at offset 0.5 + 0.5 row s into its own column's 2.5 s, and
  // also 2.0 s into another column's slice, where another lead is shown.
  EcgSheet sheet = flat_sheet();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      const double own = column * 2.5 + 0.5 + 0.5 * row, other = ((column + 2) % 4) * 2.5 + 2.0;
      add_pulse(sheet, kLeadAt[row][column], own, own + 0.2, 1.0);
      add_pulse(sheet, kLeadAt[row][column], other, other + 0.2, 1.0);
    }
  }
  const Image image = draw(sheet, 10);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      const double own = column * 2.5 + 0.5 + 0.5 * row + 0.1, other = column * 2.5 + 2.1;
      EXPECT_TRUE(ink_near(image, x_of(l, own), y_of(l, row, 1.0))) << kLeadAt[row][column];
      EXPECT_FALSE(ink_near(image, x_of(l, other), y_of(l, row, 1.0), 3)) << kLeadAt[row][column];
      EXPECT_TRUE(ink_near(image, x_of(l, other), l.baseline_y[row])) << kLeadAt[row][column];
    }
  }
  // V4 (first row, fourth column) shows its pulse of [7.5, 10) s there, and its pulse at
  // 4.5 s nowhere: the first row shows aVR then.
  EXPECT_TRUE(ink_near(image, x_of(l, 8.1), y_of(l, 0, 1.0)));
  EXPECT_FALSE(ink_near(image, x_of(l, 4.6), y_of(l, 0, 1.0), 3));
}

TEST(EcgSheet, RhythmStripRunsLeadTwoOverTheWholeWindow) {
  EcgSheet sheet = flat_sheet();
  add_pulse(sheet, "II", 0.1, 0.3, 1.0);
  add_pulse(sheet, "II", 9.6, 9.8, 1.0);
  const Image image = draw(sheet, 10);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  EXPECT_TRUE(ink_near(image, x_of(l, 0.2), y_of(l, 3, 1.0)));
  EXPECT_TRUE(ink_near(image, x_of(l, 9.7), y_of(l, 3, 1.0)));
  // Every pixel column from 0 s to 10 s carries the trace.
  int bare = 0;
  for (int x = int(std::ceil(x_of(l, 0))); x < int(x_of(l, 10)); ++x) {
    bare += topmost_ink(image, x, band_top(l, 3), band_bottom(l, 3)) < 0;
  }
  EXPECT_EQ(bare, 0);
  // The 3x4 rows show lead II only in column 1: V5's cell stays flat at 9.7 s.
  EXPECT_FALSE(ink_near(image, x_of(l, 9.7), y_of(l, 1, 1.0), 3));
}

TEST(EcgSheet, MissingLeadLeavesItsCellLabelledButWithoutTrace) {
  EcgSheet sheet = flat_sheet();
  for (std::size_t i = 0; i < sheet.leads.size(); ++i) {
    if (sheet.leads[i] == "V2") {
      sheet.leads.erase(sheet.leads.begin() + i);
      sheet.mv.erase(sheet.mv.begin() + i);
      break;
    }
  }
  const Image image = draw(sheet, 10);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  const double mm = l.px_per_mm;
  // V2 is in the second row, third column: [5, 7.5) s. Inside its band, away from the ticks at its edges.
  EXPECT_EQ(ink_in(image, x_of(l, 5.0) + 3, x_of(l, 7.5) - 3, band_top(l, 1), band_bottom(l, 1)), 0);
  EXPECT_GT(ink_in(image, x_of(l, 5.0), x_of(l, 5.0) + 8 * mm, l.row_top(1), band_top(l, 1)), 10);  // "V2"
  // Its neighbour V1 above it, flat, is drawn.
  EXPECT_GT(ink_in(image, x_of(l, 5.0) + 3, x_of(l, 7.5) - 3, band_top(l, 0), band_bottom(l, 0)), 100);
}

TEST(EcgSheet, NothingIsWrittenAfterTheKnownTime) {
  const EcgSheet sheet = flat_sheet();
  const Image image = draw(sheet, 5, 5);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  const double right = l.grid_x + l.grid_width;
  // The rhythm strip stops at 5 s (a pen's width of slack)...
  EXPECT_EQ(ink_in(image, x_of(l, 5) + 3, right, band_top(l, 3), band_bottom(l, 3)), 0);
  EXPECT_GT(ink_in(image, x_of(l, 4), x_of(l, 5) - 2, band_top(l, 3), band_bottom(l, 3)), 5 * 5 * 4);
  // ...and so do the 3x4 rows: columns 3 and 4 are blank but for the ticks at their edges.
  for (int row = 0; row < 3; ++row) {
    EXPECT_EQ(ink_in(image, x_of(l, 5) + 3, x_of(l, 7.5) - 3, band_top(l, row), band_bottom(l, row)), 0) << row;
    EXPECT_EQ(ink_in(image, x_of(l, 7.5) + 3, right, band_top(l, row), band_bottom(l, row)), 0) << row;
    EXPECT_TRUE(ink_near(image, x_of(l, 4.9), l.baseline_y[row])) << row;
  }
}

TEST(EcgSheet, ShowsTheTenSecondPageThatContainsNow) {
  EcgSheet sheet = flat_sheet(25);
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, -3), 0);
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, 0), 0);
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, 10), 0);  // A page's end still shows it.
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, 10.01), 10);
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, 25), 20);
  sheet.start_s = 3;
  EXPECT_DOUBLE_EQ(ecg_sheet_window_start_s(sheet, 14), 13);
  sheet.start_s = 0;

  add_pulse(sheet, "II", 14.0, 14.2, 1.0);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  const Image page_two = draw(sheet, 12);
  EXPECT_TRUE(ink_near(page_two, x_of(l, 4.1), y_of(l, 3, 1.0)));
  const Image page_one = draw(sheet, 10);
  EXPECT_FALSE(ink_near(page_one, x_of(l, 4.1), y_of(l, 3, 1.0), 3));
}

TEST(EcgSheet, CalibrationPulseIsOneMillivoltByTwoHundredMillisecondsInEveryRow) {
  EcgSheet empty;
  const Image image = draw(empty, 0);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  for (int row = 0; row < kEcgRows; ++row) {
    // Along the 1-mV level of the lead-in, the pulse's top: 200 ms at 25 mm/s = 5 mm.
    const int y = int(std::floor(y_of(l, row, 1.0)));
    int run = 0;
    for (int x = int(l.grid_x); x < int(l.trace_x); ++x) run += inked(image, x, y);
    EXPECT_NEAR(run, 0.2 * kMmPerS * l.px_per_mm, 2.0) << row;
    // Its top is 10 mm above the baseline.
    const int middle = int(l.grid_x + 5 * l.px_per_mm);
    EXPECT_NEAR(topmost_ink(image, middle, l.row_top(row), l.baseline_y[row]), y_of(l, row, 1.0), 1.5) << row;
  }
}

TEST(EcgSheet, TallDeflectionsOverlapTheRowAboveButNeverLeaveTheGrid) {
  EcgSheet sheet = flat_sheet();
  add_pulse(sheet, "I", 1.0, 1.2, 10.0);  // 100 mm: far above the sheet.
  add_pulse(sheet, "II", 1.5, 1.7, 2.0);  // 20 mm: into row 0 (its baseline is 17 mm below its top).
  const Image image = draw(sheet, 10);
  const EcgSheetLayout l = ecg_sheet_layout(kBox);
  EXPECT_EQ(ink_in(image, x_of(l, 0.9), x_of(l, 1.3), kBox.y, l.grid_y), 0);
  EXPECT_GE(topmost_ink(image, int(x_of(l, 1.1)), kBox.y, l.baseline_y[0]), l.grid_y);
  EXPECT_LT(topmost_ink(image, int(x_of(l, 1.1)), kBox.y, l.baseline_y[0]), l.grid_y + 3);  // Cut at the edge.
  ASSERT_LT(y_of(l, 1, 2.0), l.row_top(1));
  EXPECT_TRUE(ink_near(image, x_of(l, 1.6), y_of(l, 1, 2.0)));
}

TEST(EcgSheet, StillHasTheSheetsAspectShowsTheLastTenSecondsAndIsDeterministic) {
  EcgSheet sheet = flat_sheet(25);
  sheet.title = "Sinus rhythm (synthetic)";
  add_pulse(sheet, "II", 14.0, 14.2, 1.0);  // Before the last 10 s: not shown.
  add_pulse(sheet, "II", 24.0, 24.2, 1.0);  // 9 s into them.
  plot::Font font;
  const Image still = ecg_sheet_still(sheet, font, 1340);
  ASSERT_EQ(still.width, 1340);
  ASSERT_EQ(still.height, 675);
  const EcgSheetLayout l = ecg_sheet_layout(Rect{0, 0, still.width, still.height});
  EXPECT_TRUE(ink_near(still, x_of(l, 9.1), y_of(l, 3, 1.0)));
  EXPECT_FALSE(ink_near(still, x_of(l, 4.1), y_of(l, 3, 1.0), 3));  // Where the page [10, 20) shows 14 s.
  EXPECT_EQ(ecg_sheet_still(sheet, font, 1340).rgb, still.rgb);
}

TEST(EcgSheet, RefusesInvalidSheets) {
  plot::Font font;
  Image image(kBox.width, kBox.height);
  const auto code_of = [&](const EcgSheet& sheet, double now_s = 0) {
    try {
      draw_ecg_sheet(image, kBox, sheet, font, now_s);
    } catch (const Error& e) {
      return e.code();
    }
    return ExitCode::kOk;
  };
  EXPECT_EQ(code_of(flat_sheet()), ExitCode::kOk);
  EcgSheet unknown = flat_sheet();
  unknown.leads[0] = "V7";
  EXPECT_EQ(code_of(unknown), ExitCode::kDataError);
  EcgSheet twice = flat_sheet();
  twice.leads[1] = "I";
  EXPECT_EQ(code_of(twice), ExitCode::kDataError);
  EcgSheet short_of_samples = flat_sheet();
  short_of_samples.mv.pop_back();
  EXPECT_EQ(code_of(short_of_samples), ExitCode::kDataError);
  for (double rate : {0.0, -500.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EcgSheet bad_rate = flat_sheet();
    bad_rate.rate_hz = rate;
    EXPECT_EQ(code_of(bad_rate), ExitCode::kDataError) << rate;
  }
  EXPECT_EQ(code_of(flat_sheet(), std::nan("")), ExitCode::kDataError);
  EXPECT_THROW(ecg_sheet_still(flat_sheet(), font, 100), Error);
}

}  // namespace
}  // namespace systole::overlay
