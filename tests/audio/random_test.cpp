// The soundtrack's random numbers (audio/random.h): SplitMix64 against its published
// reference outputs, uniform floats in [-1, 1), and per-sound seeds that stay apart.

#include "audio/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace systole::audio {
namespace {

TEST(Random, MatchesSplitMix64sReferenceOutputs) {
  // Vigna's splitmix64.c seeded with 1234567 (Rosetta Code, "Pseudo-random numbers/Splitmix64").
  Random r(1234567);
  EXPECT_EQ(r.next(), 6457827717110365317ull);
  EXPECT_EQ(r.next(), 3203168211198807973ull);
  EXPECT_EQ(r.next(), 9817491932198370423ull);
  EXPECT_EQ(r.next(), 4593380528125082431ull);
  EXPECT_EQ(r.next(), 16408922859458223821ull);
  EXPECT_EQ(Random(0).next(), 0xe220a8397b1dcdafull);
}

TEST(Random, UniformIsInMinusOneToOneWithTheRightMoments) {
  Random r(42);
  const int n = 200000;
  double sum = 0, sum2 = 0, lo = 1, hi = -1;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, -1.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum2 += u * u;
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  // Uniform on [-1, 1): mean 0, variance 1/3; five standard errors.
  EXPECT_NEAR(sum / n, 0.0, 5 * std::sqrt(1.0 / 3 / n));
  EXPECT_NEAR(sum2 / n, 1.0 / 3, 5 * std::sqrt(4.0 / 45 / n));
  EXPECT_LT(lo, -0.999);
  EXPECT_GT(hi, 0.999);
}

TEST(Random, UniformIsTheTop53BitsExactly) {
  Random a(7), b(7);
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t bits = a.next() >> 11;
    EXPECT_EQ(b.uniform(), 2.0 * std::ldexp(static_cast<double>(bits), -53) - 1.0);
  }
}

TEST(Random, SoundSeedsDifferByKindAndIndexAndAreStable) {
  std::set<std::uint64_t> seeds;
  for (int kind = 0; kind < 4; ++kind)
    for (std::uint64_t index = 0; index < 50; ++index) seeds.insert(sound_seed(1, kind, index));
  EXPECT_EQ(seeds.size(), 200u);  // No two sounds share their noise.
  EXPECT_EQ(sound_seed(9, 2, 3), sound_seed(9, 2, 3));
  EXPECT_NE(sound_seed(9, 2, 3), sound_seed(10, 2, 3));  // The scene's seed matters.
}

}  // namespace
}  // namespace systole::audio
