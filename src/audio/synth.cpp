#include "audio/synth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "audio/random.h"

namespace systole::audio {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kAttackS = 0.002;  // Fast enough to place the onset; slow enough not to click.

/// Raised-cosine fade-in over kAttackS. unit: 1
double attack(double t_s) { return t_s >= kAttackS ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * t_s / kAttackS); }

double noise_share(SoundKind kind) {
  switch (kind) {
    case SoundKind::kS1: return 0.12;  // S1 is the rougher sound (Tilkian & Conover, ch. 3).
    case SoundKind::kS2: return 0.08;
    case SoundKind::kS3: return 0.0;   // A pure low thud.
    default: return 0.0;
  }
}

}  // namespace

std::vector<Resonance> resonances_of(SoundKind kind) {
  switch (kind) {
    // S1: mitral (M1) then tricuspid (T1) closure about 20-30 ms later; 100-150 ms long,
    // most energy 30-100 Hz, the louder and longer of the two main sounds at the apex.
    case SoundKind::kS1:
      return {{0.000, 0.85, 62, 52, 0.04, 0.030}, {0.000, 0.30, 118, 96, 0.03, 0.016},
              {0.025, 0.55, 50, 44, 0.04, 0.028}};
    // S2: aortic (A2) then pulmonary (P2) closure, each a chirp falling in pitch (Xu et al.
    // 2000), shorter (about 80 ms) and higher than S1; the split A2-P2 of 30 ms is that of
    // expiration in a young adult.
    case SoundKind::kS2:
      return {{0.000, 0.80, 135, 80, 0.03, 0.018}, {0.030, 0.45, 115, 70, 0.03, 0.016}};
    // S3: a low thud (20-50 Hz) as rapid early filling is suddenly checked, 40-50 ms long.
    case SoundKind::kS3:
      return {{0.000, 0.70, 38, 32, 0.03, 0.016}};
    // The click: a wood-block tick, well above the heart sounds so it never masks them.
    case SoundKind::kClick:
      return {{0.000, 0.60, 1800, 1800, 0, 0.0025}, {0.000, 0.35, 950, 950, 0, 0.004}};
  }
  return {};
}

std::vector<double> synthesize(SoundKind kind, std::uint64_t seed, int rate_hz) {
  const std::vector<Resonance> parts = resonances_of(kind);
  double length_s = 0;
  for (const Resonance& r : parts) length_s = std::max(length_s, r.delay_s + r.decay_s * std::log(1e4));
  const std::size_t n = static_cast<std::size_t>(std::ceil(length_s * rate_hz));
  std::vector<double> out(n, 0.0);
  for (const Resonance& r : parts) {
    double phase = 0;  // Integrated so a glide stays continuous. unit: cycles
    const std::size_t first = static_cast<std::size_t>(std::lround(r.delay_s * rate_hz));
    for (std::size_t i = first; i < n; ++i) {
      const double t = static_cast<double>(i - first) / rate_hz;
      const double f = r.glide_s > 0 && t < r.glide_s ? r.start_hz + (r.end_hz - r.start_hz) * t / r.glide_s : r.end_hz;
      out[i] += r.amplitude * attack(t) * std::exp(-t / r.decay_s) * std::sin(kTwoPi * phase);
      phase += f / rate_hz;
    }
  }
  // The noise burst: band-limited turbulence of the closing valve, decaying with the first component.
  if (const double share = noise_share(kind); share > 0) {
    BandNoise noise(seed, 150, 0.9, rate_hz);
    const double decay = parts.front().decay_s;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / rate_hz;
      out[i] += share * 3.0 * attack(t) * std::exp(-t / decay) * noise.next();
    }
  }
  return out;
}

BandNoise::BandNoise(std::uint64_t seed, double centre_hz, double q, int rate_hz) : random_(seed) {
  const double w0 = kTwoPi * centre_hz / rate_hz;
  const double alpha = std::sin(w0) / (2 * q);
  const double a0 = 1 + alpha;
  b0_ = alpha / a0;
  b2_ = -alpha / a0;
  a1_ = -2 * std::cos(w0) / a0;
  a2_ = (1 - alpha) / a0;
}

double BandNoise::next() {
  const double x = random_.uniform() * 1.7320508075688772;  // Unit variance (uniform on [-sqrt 3, sqrt 3)).
  const double y = b0_ * x + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
  x2_ = x1_;
  x1_ = x;
  y2_ = y1_;
  y1_ = y;
  return y;
}

double murmur_envelope(MurmurShape shape, double u, double window_s) {
  if (u < 0 || u > 1) return 0;
  double e = 1;
  switch (shape) {
    case MurmurShape::kDiamond: e = 1 - std::abs(2 * u - 1); break;
    case MurmurShape::kPlateau: e = 1; break;
    case MurmurShape::kDecrescendo: e = 1 - u; break;
    case MurmurShape::kCrescendo: e = u; break;
  }
  const double ramp = window_s > 0 ? std::min(0.5, 0.010 / window_s) : 0.5;
  const double edge = std::min(u, 1 - u);
  if (edge < ramp) e *= 0.5 - 0.5 * std::cos(std::numbers::pi * edge / ramp);
  return e;
}

}  // namespace systole::audio
