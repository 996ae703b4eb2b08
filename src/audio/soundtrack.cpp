#include "audio/soundtrack.h"

#include <algorithm>
#include <cmath>

#include "audio/random.h"
#include "audio/synth.h"

namespace systole::audio {
namespace {

/// Where sample i of a sound starting at sample `start` goes: in a loop, wrapped into
/// [loop_begin, n); otherwise -1 past the end. unit: samples
std::int64_t place(std::int64_t i, std::int64_t n, std::int64_t loop_begin) {
  if (i < n) return i;
  if (loop_begin < 0 || loop_begin >= n) return -1;
  return loop_begin + (i - loop_begin) % (n - loop_begin);
}

/// Flow at time t by linear interpolation (held beyond the ends). unit: m^3/s
double flow_at(const std::vector<FlowSample>& flow, double t_s) {
  if (flow.empty()) return 0;
  if (t_s <= flow.front().time_s) return flow.front().flow;
  if (t_s >= flow.back().time_s) return flow.back().flow;
  const auto hi = std::upper_bound(flow.begin(), flow.end(), t_s, [](double t, const FlowSample& s) { return t < s.time_s; });
  const auto lo = hi - 1;
  const double u = (t_s - lo->time_s) / (hi->time_s - lo->time_s);
  return lo->flow + u * (hi->flow - lo->flow);
}

void add_events(const MixRequest& r, std::vector<double>& mix, std::int64_t loop_begin) {
  const auto n = static_cast<std::int64_t>(mix.size());
  for (std::size_t e = 0; e < r.events.size(); ++e) {
    const SoundEvent& ev = r.events[e];
    const std::vector<double> sound =
        synthesize(ev.kind, sound_seed(r.seed, static_cast<int>(ev.kind), e), kSampleRateHz);
    const auto start = static_cast<std::int64_t>(std::llround(ev.time_s * kSampleRateHz));
    for (std::size_t k = 0; k < sound.size(); ++k) {
      const std::int64_t i = start + static_cast<std::int64_t>(k);
      if (i < 0) continue;
      const std::int64_t at = place(i, n, loop_begin);
      if (at >= 0) mix[static_cast<std::size_t>(at)] += ev.gain * sound[k];
    }
  }
}

void add_murmur(const MixRequest& r, std::vector<double>& mix, std::int64_t loop_begin) {
  const MurmurSound& m = r.murmur;
  if (m.gain <= 0) return;
  const auto n = static_cast<std::int64_t>(mix.size());
  for (std::size_t w = 0; w < m.windows.size(); ++w) {
    const MurmurWindow& win = m.windows[w];
    const double length = win.to_s - win.from_s;
    if (!(length > 0)) continue;
    // Turbulent flow through a narrowed or leaking valve: band-limited noise (Tilkian &
    // Conover, ch. 7); Q 2 keeps its pitch recognisable yet rough.
    BandNoise noise(sound_seed(r.seed, 100, w), m.pitch_hz, 2.0);
    const auto first = static_cast<std::int64_t>(std::llround(win.from_s * kSampleRateHz));
    const auto last = static_cast<std::int64_t>(std::llround(win.to_s * kSampleRateHz));
    for (std::int64_t i = first; i < last; ++i) {
      const double u = (static_cast<double>(i) / kSampleRateHz - win.from_s) / length;
      const double s = m.gain * murmur_envelope(m.shape, u, length) * noise.next();
      if (i < 0) continue;
      const std::int64_t at = place(i, n, loop_begin);
      if (at >= 0) mix[static_cast<std::size_t>(at)] += s;
    }
  }
}

void add_breath(const MixRequest& r, std::vector<double>& mix) {
  const BreathSound& b = r.breath;
  if (b.gain <= 0 || b.flow.empty()) return;
  double peak = 0;
  for (const FlowSample& f : b.flow) peak = std::max(peak, std::abs(f.flow));
  if (!(peak > 0)) return;
  // Vesicular breath sounds: filtered noise, most energy below 400 Hz, whose amplitude grows
  // with the air flow (sound power about the square of flow: Gavriely & Cugell, "Breath
  // Sounds Methodology", 1995, ch. 4), inspiration louder than the largely silent
  // expiration (Pasterkamp, Kraman & Wodicka, Am J Respir Crit Care Med 156, 1997).
  BandNoise low(sound_seed(r.seed, 200, 0), 250, 0.8);
  BandNoise high(sound_seed(r.seed, 201, 0), 600, 1.2);
  constexpr double kExpirationShare = 0.35;
  for (std::size_t i = 0; i < mix.size(); ++i) {
    const double t = static_cast<double>(i) / kSampleRateHz;
    const double f = flow_at(b.flow, t) / peak;
    const double a = f > 0 ? f : -kExpirationShare * f;
    mix[i] += b.gain * a * (0.8 * low.next() + 0.35 * high.next());
  }
}

}  // namespace

std::int64_t sample_count(double duration_s, int sample_rate_hz) {
  return std::max<std::int64_t>(0, std::llround(duration_s * sample_rate_hz));
}

double gain_of_db(double level_db) { return std::pow(10.0, level_db / 20.0); }

Soundtrack mix(const MixRequest& r) {
  std::vector<double> mix(static_cast<std::size_t>(sample_count(r.duration_s)), 0.0);
  const std::int64_t loop_begin = r.loop_from_s >= 0 ? sample_count(r.loop_from_s) : -1;
  add_events(r, mix, loop_begin);
  add_murmur(r, mix, loop_begin);
  add_breath(r, mix);
  Soundtrack out;
  out.samples.resize(mix.size());
  for (std::size_t i = 0; i < mix.size(); ++i) {
    // A soft limit (tanh above 0.7 of full scale) instead of clipping: loud overlaps bend, never wrap.
    double x = r.master_gain * mix[i];
    const double knee = 0.7;
    if (std::abs(x) > knee) x = std::copysign(knee + (1 - knee) * std::tanh((std::abs(x) - knee) / (1 - knee)), x);
    out.samples[i] = static_cast<float>(x);
  }
  return out;
}

}  // namespace systole::audio
