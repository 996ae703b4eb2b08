#include "overlay/ecg_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/error.h"

namespace systole::overlay {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The sheet in millimetres: the grid (a 10-mm calibration lead-in and 10 s at 25 mm/s
// across, four 30-mm rows down; both multiples of 5 mm, so the grid ends on major lines),
// a header above it for the title and caption, and a margin around.
constexpr double kMarginMm = 4;
constexpr double kHeaderMm = 11;
constexpr double kLeadInMm = 10;
constexpr double kGridWidthMm = kLeadInMm + kEcgWindow_s * kEcgPaperSpeed_mm_per_s;  // 260 mm
constexpr double kRowMm = 30;
constexpr double kGridHeightMm = kEcgRows * kRowMm;  // 120 mm
constexpr double kSheetWidthMm = kMarginMm + kGridWidthMm + kMarginMm;  // 268 mm
constexpr double kSheetHeightMm = kHeaderMm + kGridHeightMm + kMarginMm;  // 135 mm
// The baseline sits below the middle of its row: R waves rise higher than S waves fall,
// and the lead's label takes the row's top left corner.
constexpr double kBaselineMm = 17;

// Printed ECG paper: a white-pink sheet, pale red millimetre lines, darker 5-mm lines,
// the trace in near-black ink.
constexpr Rgb kPaper{255, 247, 245};
constexpr Rgb kMinorLine{246, 196, 196};
constexpr Rgb kMajorLine{226, 122, 122};
constexpr Rgb kInk{22, 20, 24};
constexpr Rgb kText{44, 30, 30};

// The usual 3x4 layout; the rhythm strip below it is lead II.
constexpr std::array<std::array<const char*, 4>, 3> kLeadAt = {{{"I", "aVR", "V1", "V4"},
                                                                {"II", "aVL", "V2", "V5"},
                                                                {"III", "aVF", "V3", "V6"}}};
constexpr const char* kRhythmLead = "II";

bool is_lead_name(const std::string& name) {
  for (const auto& row : kLeadAt) {
    if (std::find(row.begin(), row.end(), name) != row.end()) return true;
  }
  return false;
}

void validate(const EcgSheet& sheet) {
  auto fail = [](const std::string& what) { throw Error(ExitCode::kDataError, "ECG sheet: " + what); };
  if (!(std::isfinite(sheet.rate_hz) && sheet.rate_hz > 0)) fail("the sample rate must be positive and finite (Hz)");
  if (!std::isfinite(sheet.start_s)) fail("the start time must be finite (s)");
  if (sheet.leads.size() != sheet.mv.size()) {
    fail(std::to_string(sheet.leads.size()) + " lead names but " + std::to_string(sheet.mv.size()) +
         " lists of samples");
  }
  for (std::size_t i = 0; i < sheet.leads.size(); ++i) {
    const std::string& name = sheet.leads[i];
    if (!is_lead_name(name)) fail("unknown lead '" + name + "' (known: I II III aVR aVL aVF V1 V2 V3 V4 V5 V6)");
    if (std::find(sheet.leads.begin(), sheet.leads.begin() + i, name) != sheet.leads.begin() + i) {
      fail("lead '" + name + "' is given twice");
    }
  }
}

/// The samples of lead `name`; null when the sheet does not have it.
const std::vector<double>* samples_of(const EcgSheet& sheet, const std::string& name) {
  for (std::size_t i = 0; i < sheet.leads.size(); ++i) {
    if (sheet.leads[i] == name) return &sheet.mv[i];
  }
  return nullptr;
}

/// The end of the longest lead: its last sample lasts one sample period. unit: s
double recording_end_s(const EcgSheet& sheet) {
  std::size_t n = 0;
  for (const auto& mv : sheet.mv) n = std::max(n, mv.size());
  return sheet.start_s + double(n) / sheet.rate_hz;
}

/// One lead as the pen sees it: only what is known by `known_until_s`.
struct Lead {
  const std::vector<double>& mv;
  double rate_hz, start_s, known_until_s;

  double time_of(std::size_t k) const { return start_s + double(k) / rate_hz; }
  bool known(std::size_t k) const { return k < mv.size() && time_of(k) <= known_until_s + 1e-9; }

  /// The value at `t_s`, linear between samples; NaN outside the samples, in a gap, or
  /// where either neighbouring sample is not known yet. unit: mV
  double at(double t_s) const {
    if (!(t_s >= start_s)) return kNaN;
    const double f = (t_s - start_s) * rate_hz;
    const double nearest = std::round(f);
    // On a sample (within rounding), that sample alone: the next may not be known yet.
    if (std::abs(f - nearest) < 1e-6) {
      const auto k = static_cast<std::size_t>(nearest);
      return known(k) && std::isfinite(mv[k]) ? mv[k] : kNaN;
    }
    const auto k = static_cast<std::size_t>(f);
    if (!known(k + 1)) return kNaN;
    const double v = mv[k] + (f - double(k)) * (mv[k + 1] - mv[k]);
    return std::isfinite(v) ? v : kNaN;
  }

  /// The lowest and highest of `v` and every known sample in [ta_s, tb_s], so a spike
  /// narrower than a pixel (the R wave, a step) still spans its column. unit: mV
  std::pair<double, double> extremes(double ta_s, double tb_s, double v) const {
    double lo = v, hi = v;
    const double first = std::max(0.0, std::ceil((ta_s - start_s) * rate_hz - 1e-9));
    for (auto k = static_cast<std::size_t>(first); known(k) && time_of(k) <= tb_s; ++k) {
      if (std::isfinite(mv[k])) lo = std::min(lo, mv[k]), hi = std::max(hi, mv[k]);
    }
    return {lo, hi};
  }
};

/// The trace's ink: antialiased lines, cut at the grid's top and bottom so no line leaves
/// the sheet (the coverage of a line reaches half its width and half a pixel past it).
struct Pen {
  plot::Canvas& canvas;
  double width_px;
  double top, bottom;  ///< unit: px

  double clamped(double y) const {
    const double inset = 0.5 * width_px + 0.5;
    return std::clamp(y, top + inset, bottom - inset);
  }
  void line(double x0, double y0, double x1, double y1) const {
    canvas.line(x0, clamped(y0), x1, clamped(y1), kInk, width_px);
  }
};

/// Draws `lead` from `from_s` to `to_s` (absolute times) in row `row`, one pixel column at
/// a time: the value at the column's centre joins the previous column's, and the column's
/// lowest..highest keeps spikes that fall between centres. A gap breaks the line.
void draw_span(const Pen& pen, const EcgSheetLayout& layout, const Lead& lead, int row, double from_s, double to_s,
               double window_start_s) {
  const double x0 = layout.x_at(from_s - window_start_s), x1 = layout.x_at(to_s - window_start_s);
  const double s_per_px = 1.0 / (kEcgPaperSpeed_mm_per_s * layout.px_per_mm);
  const auto time_at = [&](double x) { return from_s + (x - x0) * s_per_px; };
  double prev_x = 0, prev_y = kNaN;
  for (int px = int(std::floor(x0)); px < int(std::ceil(x1)); ++px) {
    const double xc = px + 0.5;
    if (xc < x0 || xc >= x1) continue;
    const double v = lead.at(time_at(xc));
    if (std::isnan(v)) {
      prev_y = kNaN;
      continue;
    }
    const auto [lo, hi] = lead.extremes(time_at(std::max<double>(px, x0)), time_at(std::min<double>(px + 1, x1)), v);
    const double y = pen.clamped(layout.y_at(row, v));
    if (!std::isnan(prev_y)) pen.line(prev_x, prev_y, xc, y);
    const double y_lo = pen.clamped(layout.y_at(row, lo)), y_hi = pen.clamped(layout.y_at(row, hi));
    if (y_lo - y_hi > 1) pen.line(xc, y_hi, xc, y_lo);
    prev_x = xc;
    prev_y = y;
  }
}

/// Draws every row's traces: in rows 0-2, column c shows its lead over its 2.5 s of the
/// window; row 3 shows lead II over all of it.
void draw_traces(const Pen& pen, const EcgSheetLayout& layout, const EcgSheet& sheet, double window_start_s,
                 double known_until_s) {
  const auto draw = [&](const char* name, int row, double from_s, double to_s) {
    if (const std::vector<double>* mv = samples_of(sheet, name)) {
      draw_span(pen, layout, Lead{*mv, sheet.rate_hz, sheet.start_s, known_until_s}, row, from_s, to_s,
                window_start_s);
    }
  };
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      const double from_s = window_start_s + column * kEcgColumn_s;
      draw(kLeadAt[row][column], row, from_s, from_s + kEcgColumn_s);
    }
  }
  draw(kRhythmLead, 3, window_start_s, window_start_s + kEcgWindow_s);
}

/// The paper: minor lines every millimetre (only where a millimetre is at least 3 px: any
/// closer and they merge into a flat tint that hides the major lines), then major lines
/// every 5 mm over them, thicker on a fine raster so they stay the darker grid.
void draw_paper(plot::Canvas& canvas, const Rect& box, const EcgSheetLayout& layout) {
  canvas.fill(box.x, box.y, box.right(), box.bottom(), kPaper);
  const double mm = layout.px_per_mm;
  const int x0 = int(layout.grid_x), y0 = int(layout.grid_y);
  const int x1 = int(std::lround(layout.grid_x + layout.grid_width)) + 1;
  const int y1 = int(std::lround(layout.grid_y + layout.grid_height)) + 1;
  const auto draw_lines = [&](int every_mm, int thickness, const Rgb& color) {
    for (int k = 0; k <= int(kGridWidthMm); k += every_mm) {
      const int x = int(std::lround(layout.grid_x + k * mm));
      canvas.fill(x, y0, x + thickness, y1, color);
    }
    for (int k = 0; k <= int(kGridHeightMm); k += every_mm) {
      const int y = int(std::lround(layout.grid_y + k * mm));
      canvas.fill(x0, y, x1, y + thickness, color);
    }
  };
  if (mm >= 3) draw_lines(1, 1, kMinorLine);
  draw_lines(5, std::max(1, int(std::lround(mm / 5))), kMajorLine);
}

/// The 1-mV, 200-ms calibration pulse in every row's lead-in, ending on the baseline where
/// the trace begins; and a short tick where each row of leads changes lead.
void draw_calibration_and_separators(const Pen& pen, const EcgSheetLayout& layout) {
  const double mm = layout.px_per_mm;
  const double pulse_mm = 0.2 * kEcgPaperSpeed_mm_per_s;  // 200 ms
  const double rise = layout.grid_x + (kLeadInMm - pulse_mm) / 2 * mm, fall = rise + pulse_mm * mm;
  for (int row = 0; row < kEcgRows; ++row) {
    const double base = layout.y_at(row, 0), top = layout.y_at(row, 1.0);
    const double xs[] = {layout.grid_x + 1 * mm, rise, rise, fall, fall, layout.trace_x};
    const double ys[] = {base, base, top, top, base, base};
    for (int i = 0; i + 1 < 6; ++i) pen.line(xs[i], ys[i], xs[i + 1], ys[i + 1]);
  }
  for (int row = 0; row < 3; ++row) {
    for (int column = 1; column < 4; ++column) {
      const double x = layout.x_at(column * kEcgColumn_s);
      pen.line(x, layout.y_at(row, 0.3), x, layout.y_at(row, -0.3));
    }
  }
}

/// Each cell's lead name in its top left corner, over a halo of paper so it reads where a
/// tall deflection of the row below crosses it; missing leads are labelled too.
void draw_labels(plot::Canvas& canvas, const EcgSheetLayout& layout, plot::Font& font) {
  const double mm = layout.px_per_mm;
  font.size(std::max(7, int(std::lround(4 * mm))));
  const double halo = std::max(1.0, std::round(0.4 * mm));
  const auto label = [&](const char* name, int row, int column) {
    const double x = layout.x_at(column * kEcgColumn_s) + 1.2 * mm;
    const double y = layout.row_top(row) + 1.5 * mm + font.ascent();
    font.draw_with_halo(canvas, name, x, y, kText, kPaper, halo, 1.0);
  };
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) label(kLeadAt[row][column], row, column);
  }
  label(kRhythmLead, 3, 0);
}

/// The title on the left above the grid; on the right the window shown, the paper speed
/// and the gain, so a reader can measure intervals and voltages from the grid.
void draw_header(plot::Canvas& canvas, const EcgSheetLayout& layout, const std::string& title, plot::Font& font,
                 double window_start_s) {
  const double mm = layout.px_per_mm;
  font.size(std::max(8, int(std::lround(4.5 * mm))));
  const double baseline = layout.grid_y - 3 * mm;
  if (!title.empty()) font.draw(canvas, title, layout.grid_x, baseline, kText);
  char caption[128];
  std::snprintf(caption, sizeof caption, "%.1f\u2013%.1f s    %g mm/s  %g mm/mV", window_start_s,
                window_start_s + kEcgWindow_s, kEcgPaperSpeed_mm_per_s, kEcgGain_mm_per_mV);
  font.draw(canvas, caption, layout.grid_x + layout.grid_width - font.width(caption), baseline, kText);
}

/// Draws a valid sheet showing [window_start_s, window_start_s + 10 s).
void draw_window(Image& image, const Rect& box, const EcgSheet& sheet, plot::Font& font, double window_start_s,
                 double known_until_s) {
  if (box.width <= 0 || box.height <= 0) return;
  const EcgSheetLayout layout = ecg_sheet_layout(box);
  plot::Canvas canvas(image);
  draw_paper(canvas, box, layout);
  // An ECG pen is about 0.3 mm wide; at least 1.5 px so a line between two pixel rows
  // still inks both darkly (an antialiased 1-px line would leave two grey half-lines).
  const Pen pen{canvas, std::clamp(0.3 * layout.px_per_mm, 1.5, 3.0), layout.grid_y,
                layout.grid_y + layout.grid_height + 1};
  draw_traces(pen, layout, sheet, window_start_s, known_until_s);
  draw_calibration_and_separators(pen, layout);
  draw_labels(canvas, layout, font);
  draw_header(canvas, layout, sheet.title, font, window_start_s);
}

}  // namespace

EcgSheetLayout ecg_sheet_layout(const Rect& box) {
  EcgSheetLayout layout;
  const double mm = std::max(0.0, std::min(box.width / kSheetWidthMm, box.height / kSheetHeightMm));
  layout.px_per_mm = mm;
  // Whole pixels for the grid's corner, so its lines fall alike at any box position.
  layout.grid_x = std::round(box.x + 0.5 * (box.width - kSheetWidthMm * mm) + kMarginMm * mm);
  layout.grid_y = std::round(box.y + 0.5 * (box.height - kSheetHeightMm * mm) + kHeaderMm * mm);
  layout.grid_width = kGridWidthMm * mm;
  layout.grid_height = kGridHeightMm * mm;
  layout.trace_x = layout.grid_x + kLeadInMm * mm;
  layout.row_height = kRowMm * mm;
  for (int row = 0; row < kEcgRows; ++row) layout.baseline_y[row] = layout.row_top(row) + kBaselineMm * mm;
  return layout;
}

double ecg_sheet_window_start_s(const EcgSheet& sheet, double now_s) {
  // Page k covers (start + 10 k, start + 10 (k + 1)]: its end still shows it, so the last
  // frame of a 10-s clip shows the whole clip rather than an empty next page.
  const double page = std::ceil((now_s - sheet.start_s) / kEcgWindow_s - 1e-9) - 1;
  return sheet.start_s + std::max(0.0, page) * kEcgWindow_s;
}

void draw_ecg_sheet(Image& image, const Rect& box, const EcgSheet& sheet, plot::Font& font, double now_s,
                    double known_until_s) {
  validate(sheet);
  if (!std::isfinite(now_s)) throw Error(ExitCode::kDataError, "ECG sheet: the current time must be finite (s)");
  if (std::isnan(known_until_s)) throw Error(ExitCode::kDataError, "ECG sheet: the known-until time is NaN");
  draw_window(image, box, sheet, font, ecg_sheet_window_start_s(sheet, now_s), known_until_s);
}

Image ecg_sheet_still(const EcgSheet& sheet, plot::Font& font, int width_px) {
  validate(sheet);
  if (width_px < int(kSheetWidthMm) || width_px > 16384) {
    throw Error(ExitCode::kUsage, "ECG sheet: a still must be 268 to 16384 px wide (at least 1 px per mm), not " +
                                      std::to_string(width_px));
  }
  const int height_px = int(std::lround(width_px * kSheetHeightMm / kSheetWidthMm));
  Image image(width_px, height_px);
  const double window_start_s = std::max(sheet.start_s, recording_end_s(sheet) - kEcgWindow_s);
  draw_window(image, Rect{0, 0, width_px, height_px}, sheet, font, window_start_s,
              std::numeric_limits<double>::infinity());
  return image;
}

}  // namespace systole::overlay
