#include "electro/ecg_measure.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/error.h"

namespace systole::electro {
namespace {

/// The eight independent leads (I, II, V1-V6): the others are their sums.
constexpr std::array<int, 8> kIndependent = {0, 1, 6, 7, 8, 9, 10, 11};
constexpr double kEdgeShare = 0.05;  ///< A wave's edge: where its measure falls below this share of its peak.
constexpr double kQuietS = 0.010;    ///< A QRS ends where the slope stays low this long. unit: s

struct Globals {
  std::vector<double> slope;      ///< The leads' combined slope. unit: mV/s
  std::vector<double> amplitude;  ///< Their combined distance from the baseline. unit: mV
};

Globals globals(const Ecg& ecg, std::size_t from, std::size_t to) {
  Globals g{std::vector<double>(to - from), std::vector<double>(to - from)};
  for (std::size_t i = from; i < to; ++i) {
    double slope = 0, amplitude = 0;
    for (int l : kIndependent) {
      const std::vector<double>& x = ecg.mv[static_cast<std::size_t>(l)];
      const std::size_t a = i > 0 ? i - 1 : i, b = std::min(i + 1, x.size() - 1);
      const double d = (x[b] - x[a]) * ecg.rate_hz / double(b - a);
      slope += d * d;
      amplitude += x[i] * x[i];
    }
    g.slope[i - from] = std::sqrt(slope);
    g.amplitude[i - from] = std::sqrt(amplitude);
  }
  return g;
}

std::size_t argmax(const std::vector<double>& v, std::size_t from, std::size_t to) {
  return static_cast<std::size_t>(std::max_element(v.begin() + static_cast<long>(from), v.begin() + static_cast<long>(to)) - v.begin());
}

/// From `peak`, steps by `dir` until the slope has stayed below `low` for kQuietS: the QRS's edge.
std::size_t quiet_edge(const std::vector<double>& slope, std::size_t peak, int dir, double low, std::size_t quiet) {
  std::size_t i = peak, run = 0;
  while (run < quiet) {
    if ((dir < 0 && i == 0) || (dir > 0 && i + 1 >= slope.size())) return i;
    i = static_cast<std::size_t>(static_cast<long>(i) + dir);
    run = slope[i] < low ? run + 1 : 0;
  }
  return static_cast<std::size_t>(static_cast<long>(i) - dir * static_cast<long>(quiet - 1));
}

/// How long the wave holding sample `at` stays off the baseline (beyond `edge`, on its
/// side), within samples [on, off]. unit: samples
std::size_t wave_width(const std::vector<double>& x, std::size_t at, std::size_t on, std::size_t off, double edge) {
  const double sign = x[at] >= 0 ? 1 : -1;
  std::size_t a = at, b = at;
  while (a > on && sign * x[a - 1] > edge) --a;
  while (b < off && sign * x[b + 1] > edge) ++b;
  return b - a + 1;
}

/// A lead's QRS deflections over samples [on, off].
LeadWaves qrs_waves(const std::vector<double>& x, std::size_t on, std::size_t off, double dt) {
  LeadWaves w;
  double biggest = 0;
  std::size_t r_at = on, s_at = on;
  for (std::size_t i = on; i <= off; ++i) {
    if (x[i] > w.r) w.r = x[i], r_at = i;
    if (-x[i] > w.s) w.s = -x[i], s_at = i;
    w.qrs_area += x[i] * dt;
    biggest = std::max(biggest, std::abs(x[i]));
  }
  const double edge = kEdgeShare * biggest;
  // The S is the negative wave after the R (before it, a q); a QS complex is all S.
  if (w.r > edge) {
    w.r_duration_s = double(wave_width(x, r_at, on, off, edge)) * dt;
    s_at = r_at;
    for (std::size_t i = r_at; i <= off; ++i) s_at = x[i] < x[s_at] ? i : s_at;
  }
  if (-x[s_at] > edge) w.s_duration_s = double(wave_width(x, s_at, on, off, edge)) * dt;
  // The first deflection: a q when it goes down and an R follows.
  std::size_t i = on;
  while (i <= off && std::abs(x[i]) < edge) ++i;
  if (i <= off && x[i] < 0) {
    double depth = 0;
    for (; i <= off && x[i] < 0; ++i) depth = std::max(depth, -x[i]);
    if (i <= off) w.q = depth;
  }
  // Positive peaks above a fifth of the R, two counted apart only when the dip between
  // them falls below 85 % of the lower (a notch or an R').
  std::vector<std::pair<double, std::size_t>> peaks;
  double dip = 0;
  for (std::size_t k = on + 1; k < off; ++k) {
    if (!peaks.empty()) dip = std::min(dip, x[k]);
    if (x[k] < 0.2 * w.r || x[k] < x[k - 1] || x[k] < x[k + 1]) continue;
    if (peaks.empty() || dip < 0.85 * std::min(peaks.back().first, x[k])) {
      peaks.emplace_back(x[k], k);
    } else if (x[k] > peaks.back().first) {
      peaks.back() = {x[k], k};
    }
    dip = x[k];
  }
  w.r_peaks = static_cast<int>(peaks.size());
  if (peaks.size() >= 2) w.r_prime = peaks[1].first;
  if (!peaks.empty()) w.r_peak_time_s = double(peaks.back().second - on) * dt;
  return w;
}

}  // namespace

int lead_index(const std::string& name) {
  const std::vector<std::string>& names = standard_leads();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

BeatMeasures measure_beat(const Ecg& ecg, double from_s, double to_s, double cycle_s) {
  const double dt = 1.0 / ecg.rate_hz;
  const auto index = [&](double t) {
    return static_cast<std::size_t>(std::clamp(std::round((t - ecg.start_s) * ecg.rate_hz), 0.0, double(ecg.samples())));
  };
  const std::size_t from = index(from_s), to = index(to_s);
  if (ecg.mv.size() != 12 || to <= from + 10) throw Error(ExitCode::kInternal, "an ECG beat to measure needs twelve leads and samples");
  const Globals g = globals(ecg, 0, ecg.samples());
  const std::size_t peak = argmax(g.slope, from, to);
  const double low = kEdgeShare * g.slope[peak];
  const std::size_t quiet = static_cast<std::size_t>(std::ceil(kQuietS * ecg.rate_hz));
  const std::size_t on = quiet_edge(g.slope, peak, -1, low, quiet), off = quiet_edge(g.slope, peak, +1, low, quiet);

  BeatMeasures m;
  const auto time = [&](std::size_t i) { return ecg.start_s + double(i) * dt; };
  m.qrs_onset_s = time(on);
  m.qrs_offset_s = time(off);
  // The P wave: the combined amplitude's peak before the QRS, back to where it starts.
  const std::size_t p_end = on > from + quiet ? on - quiet : from + 1;
  std::size_t p = argmax(g.amplitude, from, p_end);
  const double p_edge = kEdgeShare * g.amplitude[p];
  while (p > from && g.amplitude[p - 1] >= p_edge) --p;
  m.p_onset_s = time(p);
  // The T wave: the combined amplitude's peak after the QRS, on to where it ends.
  const std::size_t t_from = std::min(off + static_cast<std::size_t>(0.06 * ecg.rate_hz), to - 1);
  const std::size_t t_peak = argmax(g.amplitude, t_from, to);
  std::size_t t_end = t_peak;
  while (t_end + 1 < to && g.amplitude[t_end] >= kEdgeShare * g.amplitude[t_peak]) ++t_end;
  m.t_end_s = time(t_end);

  m.pr_s = m.qrs_onset_s - m.p_onset_s;
  m.qrs_s = m.qrs_offset_s - m.qrs_onset_s;
  m.qt_s = m.t_end_s - m.qrs_onset_s;
  m.qtc_s = m.qt_s / std::sqrt(cycle_s);
  for (std::size_t l = 0; l < 12; ++l) {
    m.leads[l] = qrs_waves(ecg.mv[l], on, off, dt);
    for (std::size_t i = off; i <= t_end; ++i) {
      if (std::abs(ecg.mv[l][i]) > std::abs(m.leads[l].t)) m.leads[l].t = ecg.mv[l][i];
    }
  }
  // Lead I at 0 deg and aVF at +90 deg; aVF sees sqrt(3)/2 of the frontal vector's share.
  m.axis_deg = std::atan2(m.leads[5].qrs_area * 2 / std::sqrt(3.0), m.leads[0].qrs_area) * 180 / std::numbers::pi;
  for (int v = 0; v < 6 && m.transition == 7; ++v) {
    const LeadWaves& w = m.leads[static_cast<std::size_t>(6 + v)];
    if (w.r >= w.s) m.transition = v + 1;
  }
  return m;
}

}  // namespace systole::electro
