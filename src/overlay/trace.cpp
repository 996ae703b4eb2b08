#include "overlay/trace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace systole::overlay {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Width of a sweep in time: the window, or the whole clip. unit: s
double page_s(const Trace& t) { return t.window_s >= t.clip_s || t.window_s <= 0 ? t.clip_s : t.window_s; }

/// The time shown at fraction `p` of the width, at time `now`; NaN: nothing there.
/// `ahead`: the time is after the cursor (only when the whole clip is shown).
double shown_time(const Trace& t, double p, double now, bool& ahead) {
  const double w = page_s(t);
  const bool whole = w >= t.clip_s;
  const double start = whole ? 0.0 : std::floor(now / w) * w;
  const double at = start + p * w;
  ahead = false;
  if (at <= now) return at;
  if (whole) {
    ahead = true;
    return at;
  }
  // The previous sweep, after a gap the cursor has just erased.
  constexpr double kErased = 0.04;
  if (p * w - (now - start) < kErased * w || at - w < 0) return kNaN;
  return at - w;
}

std::string value_text(double v, const std::string& unit) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g %s", v, unit.c_str());
  return text;
}

}  // namespace

double sample(const Trace& trace, double t_s) {
  if (!(t_s >= 0) || t_s > trace.known_until_s + 1e-9) return kNaN;
  const double f = t_s / trace.sample_dt_s;
  // On a sample (within rounding), that sample alone: the next may not be known yet.
  const double nearest = std::round(f);
  if (std::abs(f - nearest) < 1e-6) {
    const auto i = static_cast<std::size_t>(nearest);
    return i < trace.values.size() ? trace.values[i] : kNaN;
  }
  const auto i = static_cast<std::size_t>(f);
  if (i + 1 >= trace.values.size()) return kNaN;
  const double u = f - double(i);
  return trace.values[i] + u * (trace.values[i + 1] - trace.values[i]);
}

Rect trace_plot_area(const Rect& box, const plot::Font& font) {
  const int pad = std::max(3, font.size() / 2);
  const int top = box.y + 2 * pad + static_cast<int>(std::ceil(font.ascent()));
  return {box.x + pad, top, std::max(1, box.width - 2 * pad), std::max(1, box.bottom() - pad - top)};
}

double cursor_x(const Rect& plot, const Trace& trace, double now_s) {
  const double w = page_s(trace);
  const double start = w >= trace.clip_s ? 0.0 : std::floor(now_s / w) * w;
  return plot.x + std::clamp((now_s - start) / w, 0.0, 1.0) * plot.width;
}

namespace {

// The value range: given, or every value known so far (it settles after the first cycle).
std::pair<double, double> value_range(const Trace& trace, double now_s) {
  double lo = trace.min, hi = trace.max;
  if (!(lo < hi)) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (std::size_t i = 0; i < trace.values.size() && double(i) * trace.sample_dt_s <= now_s + 1e-9; ++i) {
      if (std::isfinite(trace.values[i])) {
        lo = std::min(lo, trace.values[i]);
        hi = std::max(hi, trace.values[i]);
      }
    }
    if (!(lo <= hi)) lo = 0, hi = 1;
    const double margin = hi > lo ? 0.1 * (hi - lo) : std::max(1e-9, 0.05 * std::abs(hi)) + 1e-9;
    lo -= margin;
    hi += margin;
  }
  return {lo, hi};
}

// Widens a column's [vlo, vhi] to every value between its edges ta and tb, so spikes (the
// R wave) that fall between pixel centres still show.
void widen_to_column(const Trace& trace, double ta, double tb, double w, double& vlo, double& vhi) {
  if (!std::isnan(ta) && !std::isnan(tb) && tb > ta && tb - ta < w) {
    for (double s : {sample(trace, ta), sample(trace, tb)}) {
      if (!std::isnan(s)) vlo = std::min(vlo, s), vhi = std::max(vhi, s);
    }
    for (auto i = static_cast<std::size_t>(std::ceil(ta / trace.sample_dt_s));
         double(i) * trace.sample_dt_s < tb && i < trace.values.size(); ++i) {
      if (double(i) * trace.sample_dt_s <= trace.known_until_s && std::isfinite(trace.values[i]))
        vlo = std::min(vlo, trace.values[i]), vhi = std::max(vhi, trace.values[i]);
    }
  }
}

}  // namespace

void draw_trace(Image& image, const Rect& box, const Trace& trace, double now_s, plot::Font& font,
                const Style& style) {
  plot::Canvas canvas(image);
  canvas.fill(box.x, box.y, box.right(), box.bottom(), style.panel, style.panel_alpha);
  const Rect plot = trace_plot_area(box, font);
  const int pad = std::max(3, font.size() / 2);
  const double title_y = box.y + pad + font.ascent() * 0.8;
  font.draw(canvas, trace.title, box.x + pad, title_y, style.ink);
  const std::pair<double, double> range = value_range(trace, now_s);
  const double lo = range.first, hi = range.second;
  const auto to_y = [&](double v) { return plot.bottom() - (v - lo) / (hi - lo) * plot.height; };
  canvas.line(plot.x, plot.bottom() - 0.5, plot.right(), plot.bottom() - 0.5, style.ink, 1);  // A faint baseline.

  // One column per pixel: the centre value joins the previous column's, and the column's
  // min..max span keeps spikes (the R wave) that fall between pixel centres.
  const double w = page_s(trace);
  const double line = std::max(1.0, font.size() / 10.0);
  const Rgb dim{static_cast<std::uint8_t>(trace.color[0] / 2 + 20), static_cast<std::uint8_t>(trace.color[1] / 2 + 20),
                static_cast<std::uint8_t>(trace.color[2] / 2 + 20)};
  double prev_x = 0, prev_y = kNaN;
  for (int c = 0; c < plot.width; ++c) {
    const double x = plot.x + c + 0.5;
    bool ahead = false, ahead_a = false, ahead_b = false;
    const double t = shown_time(trace, (c + 0.5) / plot.width, now_s, ahead);
    const double ta = shown_time(trace, double(c) / plot.width, now_s, ahead_a);
    const double tb = shown_time(trace, double(c + 1) / plot.width, now_s, ahead_b);
    const double v = std::isnan(t) ? kNaN : sample(trace, t);
    if (std::isnan(v)) {
      prev_y = kNaN;
      continue;
    }
    double vlo = v, vhi = v;
    widen_to_column(trace, ta, tb, w, vlo, vhi);
    const Rgb& color = ahead ? dim : trace.color;
    const double y = to_y(v);
    if (!std::isnan(prev_y)) canvas.line(prev_x, prev_y, x, y, color, line);
    if (to_y(vlo) - to_y(vhi) > 1) canvas.line(x, to_y(vhi), x, to_y(vlo), color, line);
    prev_x = x;
    prev_y = y;
  }

  const double cx = cursor_x(plot, trace, now_s);
  canvas.line(cx, plot.y, cx, plot.bottom(), style.ink, line);
  const double now_value = sample(trace, std::min(now_s, trace.known_until_s));
  if (std::isfinite(now_value)) {
    canvas.line(cx, to_y(now_value), cx, to_y(now_value), trace.color, 4 * line);
    if (!trace.unit.empty()) {
      const std::string text = value_text(now_value, trace.unit);
      font.draw(canvas, text, box.right() - pad - font.width(text), title_y, trace.color);
    }
  }
}

double ecg_value(double t_s, const std::vector<double>& r_times_s, const std::vector<double>* p_times_s) {
  // Gaussian waves (McSharry et al. 2003 use the same sum-of-Gaussians shapes): amplitude in
  // mV, centre and width in s relative to the R peak.
  struct Wave {
    double amplitude, at_s, width_s;
  };
  constexpr Wave kP{0.15, 0.0, 0.025};
  constexpr double kPr = 0.16;  // Sinus rhythm's PR interval. unit: s
  auto gauss = [](double t, const Wave& w, double centre) {
    const double d = (t - centre - w.at_s) / w.width_s;
    return w.amplitude * std::exp(-0.5 * d * d);
  };
  double v = 0;
  for (auto r = std::lower_bound(r_times_s.begin(), r_times_s.end(), t_s - 1.0);
       r != r_times_s.end() && *r < t_s + 0.4; ++r) {
    const double rr = r + 1 != r_times_s.end() ? r[1] - r[0] : r != r_times_s.begin() ? r[0] - r[-1] : 0.8;
    const double bazett = std::sqrt(std::clamp(rr, 0.25, 2.0));
    const Wave waves[] = {{-0.12, -0.03, 0.009}, {1.0, 0.0, 0.011}, {-0.25, 0.03, 0.010}, {0.30, 0.30 * bazett, 0.05 * bazett}};
    for (const Wave& w : waves) v += gauss(t_s, w, *r);
    if (!p_times_s) v += gauss(t_s, kP, *r - kPr);
  }
  if (p_times_s) {
    for (auto p = std::lower_bound(p_times_s->begin(), p_times_s->end(), t_s - 0.2);
         p != p_times_s->end() && *p < t_s + 0.2; ++p) {
      v += gauss(t_s, kP, *p);
    }
  }
  return v;
}

}  // namespace systole::overlay
