#pragma once
// The soundtrack's own random numbers: SplitMix64 (Steele, Lea & Flood, "Fast splittable
// pseudorandom number generators", OOPSLA 2014), mapped to floats by bit arithmetic only.
// std::uniform_real_distribution and friends may differ between standard libraries; this
// gives the same noise everywhere for the same seed.

#include <cstdint>

namespace systole::audio {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [-1, 1): the top 53 bits as a double in [0, 1), exactly. unit: 1
  double uniform() { return 2.0 * static_cast<double>(next() >> 11) * 0x1.0p-53 - 1.0; }

 private:
  std::uint64_t state_;
};

/// A seed for one sound of a soundtrack: the scene's seed mixed with the sound's kind and
/// index, so adding a sound does not change the noise of the others.
inline std::uint64_t sound_seed(std::uint64_t seed, int kind, std::uint64_t index) {
  Random r(seed ^ (0x51ED270B7A3F1C5Dull * static_cast<std::uint64_t>(kind + 1)) ^ (index * 0xD1B54A32D192ED03ull));
  return r.next();
}

}  // namespace systole::audio
