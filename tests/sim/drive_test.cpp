#include "sim/drive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace systole::sim {
namespace {

sim::Drive make(sim::Waveform w, double rate_hz) {
  sim::Drive d;
  d.waveform = w;
  d.rate_hz = rate_hz;
  d.amplitude = 0.1;
  return d;
}

TEST(Drive, SineIsPeriodicBetweenZeroAndOne) {
  const auto d = make(sim::Waveform::kSine, 2.0);
  for (double t = 0; t < 2; t += 0.013) {
    const double phi = activation(d, t, 10);
    EXPECT_GE(phi, 0.0);
    EXPECT_LE(phi, 1.0);
    EXPECT_NEAR(phi, activation(d, t + 0.5, 10), 1e-9) << "period is 1/rate";
  }
  EXPECT_NEAR(activation(d, 0.25, 10), 1.0, 1e-12) << "peak at half a period";
  EXPECT_NEAR(activation(d, 0.0, 10), 0.0, 1e-12);
}

TEST(Drive, CardiacContractsOnlyDuringSystole) {
  auto d = make(sim::Waveform::kCardiac, 1.0);
  d.systolic_fraction = 0.3;
  EXPECT_NEAR(activation(d, 0.15, 10), 1.0, 1e-12) << "peak in mid-systole";
  EXPECT_GT(activation(d, 0.05, 10), 0.0);
  for (double t = 0.31; t < 0.99; t += 0.05) EXPECT_EQ(activation(d, t, 10), 0.0) << "diastole at rest, t=" << t;
}

TEST(Drive, CardiacPeaksWherePeakFractionSays) {
  auto d = make(sim::Waveform::kCardiac, 1.0);
  d.systolic_fraction = 0.5;
  d.peak_fraction = 0.6;
  EXPECT_NEAR(activation(d, 0.3, 10), 1.0, 1e-12) << "peak at 0.6 of the 0.5-s window";
  EXPECT_LT(activation(d, 0.25, 10), 1.0);
  EXPECT_LT(activation(d, 0.35, 10), 1.0);
  // Half-way up the rise and down the fall: 0.15 s and 0.4 s.
  EXPECT_NEAR(activation(d, 0.15, 10), 0.5, 1e-12);
  EXPECT_NEAR(activation(d, 0.4, 10), 0.5, 1e-12);
  for (double t = 0.0; t < 0.295; t += 0.01) EXPECT_LT(activation(d, t, 10), activation(d, t + 0.01, 10)) << "rising, t=" << t;
  for (double t = 0.3; t < 0.495; t += 0.01) EXPECT_GT(activation(d, t, 10), activation(d, t + 0.01, 10)) << "falling, t=" << t;
  for (double t = 0.51; t < 0.99; t += 0.05) EXPECT_EQ(activation(d, t, 10), 0.0) << "diastole at rest, t=" << t;
  // The shorter half sets the highest frequency: a half-cosine of 0.2 s.
  EXPECT_NEAR(highest_frequency_hz(d), 1.0 / (2 * 0.2), 1e-12);
}

TEST(Drive, ASymmetricPeakIsTheClassicPulse) {
  auto d = make(sim::Waveform::kCardiac, 1.2);
  d.systolic_fraction = 0.36;
  auto skewed = d;
  skewed.peak_fraction = 0.5 + 1e-15;  // Through the skewed formula, which must agree.
  for (double t = 0; t < 1; t += 0.01) EXPECT_NEAR(activation(skewed, t, 10), activation(d, t, 10), 1e-9) << t;
  EXPECT_DOUBLE_EQ(highest_frequency_hz(d), 1.2 / 0.36);
}

TEST(Drive, DelayShiftsTheWave) {
  auto atria = make(sim::Waveform::kCardiac, 1.2);
  auto ventricles = atria;
  ventricles.delay_s = 0.16;
  for (double t = 0.2; t < 2; t += 0.01) {
    EXPECT_NEAR(activation(ventricles, t, 10), activation(atria, t - 0.16, 10), 1e-12);
  }
  EXPECT_EQ(activation(ventricles, 0.1, 10), 0.0) << "no beat before the delay";
}

TEST(Drive, BreathingInhalesFasterThanItExhales) {
  auto d = make(sim::Waveform::kBreathing, 0.25);
  d.inhale_fraction = 0.4;
  // Peak at the end of the inhale, back to rest at the end of the period.
  EXPECT_NEAR(activation(d, 0.4 * 4.0, 60), 1.0, 1e-12);
  EXPECT_NEAR(activation(d, 3.999999, 60), 0.0, 1e-6);
  // Rising half takes 0.8 s of 4 s, falling half 1.2 s: the rise is steeper.
  const double rise = activation(d, 0.8, 60) - activation(d, 0.4, 60);
  const double fall = activation(d, 1.6 + 0.4, 60) - activation(d, 1.6 + 0.8, 60);
  EXPECT_GT(rise, fall);
}

TEST(Drive, RateRampIntegratesToTheRightNumberOfBeats) {
  auto d = make(sim::Waveform::kCardiac, 1.0);
  d.rate_end_hz = 2.0;
  // 1 -> 2 Hz over 10 s: mean 1.5 Hz, 15 cycles; then 2 Hz.
  EXPECT_NEAR(drive_cycles(d, 10.0, 10.0), 15.0, 1e-12);
  EXPECT_NEAR(drive_cycles(d, 12.0, 10.0), 19.0, 1e-12);
  EXPECT_NEAR(drive_cycles(d, 4.0, 0.0), 4.0, 1e-12) << "no ramp without a clip length";
}

TEST(Drive, FourierHarmonicsAddUp) {
  auto d = make(sim::Waveform::kFourier, 1.0);
  d.harmonics = {{0.3, 0.0}, {0.1, std::numbers::pi / 2}};
  for (double u = 0; u < 1; u += 0.1) {
    const double expected = 0.5 + 0.3 * std::cos(2 * std::numbers::pi * u) +
                            0.1 * std::cos(4 * std::numbers::pi * u + std::numbers::pi / 2);
    EXPECT_NEAR(waveform_value(d, u), expected, 1e-12);
  }
  EXPECT_DOUBLE_EQ(highest_frequency_hz(d), 2.0);
}

TEST(Drive, SamplesPassThroughEverySample) {
  auto d = make(sim::Waveform::kSamples, 1.0);
  d.samples = {0.0, 0.5, 1.0, 0.25};
  for (std::size_t i = 0; i < d.samples.size(); ++i) {
    EXPECT_NEAR(waveform_value(d, double(i) / d.samples.size()), d.samples[i], 1e-12);
  }
}

TEST(Drive, IrregularBeatsAreSeededAndBounded) {
  const auto a = irregular_beats(0.3, 7, 0, 50);
  EXPECT_EQ(a, irregular_beats(0.3, 7, 0, 50)) << "same seed, same rhythm";
  EXPECT_NE(a, irregular_beats(0.3, 8, 0, 50)) << "another seed, another rhythm";
  EXPECT_NE(a, irregular_beats(0.3, 7, 1, 50)) << "another region, another rhythm";
  ASSERT_GT(a.back(), 50.0);
  double shortest = 10, longest = 0;
  for (std::size_t k = 1; k < a.size(); ++k) {
    shortest = std::min(shortest, a[k] - a[k - 1]);
    longest = std::max(longest, a[k] - a[k - 1]);
  }
  EXPECT_GE(shortest, 0.7);
  EXPECT_LE(longest, 1.3);
  EXPECT_GT(longest - shortest, 0.2) << "the beats really vary";
}

TEST(Drive, IrregularBeatsStretchTheWaveform) {
  auto d = make(sim::Waveform::kCardiac, 1.0);
  d.systolic_fraction = 0.3;
  const std::vector<double> beats = {0.0, 1.5, 2.0, 3.0};
  // Beat 0 lasts 1.5 s: the peak of systole comes at 0.15 * 1.5 s.
  EXPECT_NEAR(activation(d, 0.225, 10, beats), 1.0, 1e-12);
  EXPECT_EQ(activation(d, 1.0, 10, beats), 0.0) << "diastole of the long beat";
  // Beat 1 lasts 0.5 s, from 1.5 s: its peak is at 1.5 + 0.075 s.
  EXPECT_NEAR(activation(d, 1.575, 10, beats), 1.0, 1e-12);
}

}  // namespace
}  // namespace systole::sim
