#pragma once
// The sound models (docs/sound.md): each heart sound is a few exponentially damped
// resonances - the valve leaflets and the blood and wall they set ringing - plus a short
// filtered noise burst. Heart sounds modelled as sums of damped (chirped) sinusoids follow
// Xu, Durand, Pibarot, "Nonlinear transient chirp signal modeling of the aortic and
// pulmonary components of the second heart sound", IEEE TBME 47(7), 2000, and Tran et al.
// 2004 for S1; frequencies and durations from Leatham's phonocardiography as summarised in
// Tilkian & Conover, "Understanding Heart Sounds and Murmurs" (4th ed., 2001), ch. 2-5.
// Every sound starts at its sample 0 with a 2 ms raised-cosine attack, so its onset is where
// the event is.

#include <cstdint>
#include <vector>

#include "audio/random.h"
#include "audio/soundtrack.h"

namespace systole::audio {

/// One damped resonance: amplitude * exp(-t / decay) * sin(2 pi f(t) t), f gliding
/// linearly from start_hz to end_hz over the first `glide_s` (a chirp, as A2 and P2).
struct Resonance {
  double delay_s = 0;    ///< After the sound's onset. unit: s
  double amplitude = 1;  ///< unit: full scale
  double start_hz = 50, end_hz = 50;  ///< unit: Hz
  double glide_s = 0;    ///< unit: s
  double decay_s = 0.02; ///< Time constant of the exponential decay. unit: s
};

/// The components of a sound kind, before its gain.
std::vector<Resonance> resonances_of(SoundKind kind);

/// Sound `kind` at `rate_hz` samples per second, from its onset until it has decayed below
/// 1e-4 of its peak; `seed` drives its noise burst. unit: full scale
std::vector<double> synthesize(SoundKind kind, std::uint64_t seed, int rate_hz = kSampleRateHz);

/// A biquad band-pass (Bristow-Johnson, "Audio EQ Cookbook", constant 0 dB peak gain) run
/// over white noise: the murmur's and the breath's raw sound. unit: full scale
class BandNoise {
 public:
  BandNoise(std::uint64_t seed, double centre_hz, double q, int rate_hz = kSampleRateHz);
  double next();

 private:
  Random random_;
  double b0_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

/// A murmur's loudness at `u` in [0, 1] of its window, with 10 ms ramps at both ends so it
/// does not click. unit: 1
double murmur_envelope(MurmurShape shape, double u, double window_s);

}  // namespace systole::audio
