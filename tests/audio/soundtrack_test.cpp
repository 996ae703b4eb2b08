// The sound models and the mix (docs/sound.md): every sound starts where its event is, the
// same request gives the same samples, a loop's tail wraps to its start, WAV files are
// what they say.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "audio/soundtrack.h"
#include "audio/synth.h"
#include "audio/wav.h"

namespace systole::audio {
namespace {

/// First sample whose magnitude reaches `share` of the peak.
std::size_t onset(const std::vector<float>& x, double share) {
  double peak = 0;
  for (float v : x) peak = std::max(peak, std::abs(double(v)));
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::abs(double(x[i])) >= share * peak) return i;
  return x.size();
}

TEST(Synth, EverySoundStartsAtItsFirstSampleAndDecays) {
  for (SoundKind k : {SoundKind::kS1, SoundKind::kS2, SoundKind::kS3, SoundKind::kClick}) {
    const std::vector<double> s = synthesize(k, 7);
    ASSERT_GT(s.size(), 100u);
    EXPECT_EQ(s[0], 0.0) << "a raised-cosine attack starts from silence";
    double peak = 0, tail = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      peak = std::max(peak, std::abs(s[i]));
      if (i + 48 >= s.size()) tail = std::max(tail, std::abs(s[i]));
    }
    EXPECT_GT(peak, 0.2) << int(k);
    EXPECT_LT(tail, 1e-3 * peak) << int(k) << ": still ringing at its end";
    // Reaches a tenth of its peak within 3 ms: the onset is where the event is.
    std::size_t first = 0;
    while (std::abs(s[first]) < 0.1 * peak) ++first;
    EXPECT_LT(first, 3u * kSampleRateHz / 1000) << int(k);
  }
  // S2 is shorter than S1 (Leatham): about 80 ms against 100-150 ms.
  EXPECT_LT(synthesize(SoundKind::kS2, 1).size(), synthesize(SoundKind::kS1, 1).size());
}

TEST(Mix, EventsLandOnTheirSampleAndTheSameRequestGivesTheSameSamples) {
  MixRequest r;
  r.duration_s = 1.0;
  r.events = {{SoundKind::kS1, 0.250, 1.0}};
  const Soundtrack a = mix(r), b = mix(r);
  ASSERT_EQ(a.samples.size(), 48000u);
  EXPECT_EQ(std::memcmp(a.samples.data(), b.samples.data(), a.samples.size() * sizeof(float)), 0);
  const std::size_t i = onset(a.samples, 0.05);
  EXPECT_NEAR(double(i) / kSampleRateHz, 0.250, 0.002);
  // Another seed changes the noise, not the timing.
  r.seed = 2;
  const Soundtrack c = mix(r);
  EXPECT_NE(std::memcmp(a.samples.data(), c.samples.data(), a.samples.size() * sizeof(float)), 0);
  EXPECT_NEAR(double(onset(c.samples, 0.05)) / kSampleRateHz, 0.250, 0.002);
}

TEST(Mix, ALoopsTailWrapsToItsStartAndAClipsIsCut) {
  MixRequest r;
  r.duration_s = 0.5;
  r.events = {{SoundKind::kS1, 0.45, 1.0}};  // Rings for ~130 ms: 80 ms past the end.
  const Soundtrack cut = mix(r);
  r.loop_from_s = 0.1;  // Cards before 0.1 s; the loop is [0.1, 0.5).
  const Soundtrack looped = mix(r);
  double before_cut = 0, before_loop = 0, cards = 0;
  for (std::size_t i = 4800; i < 4800 + 2400; ++i) {
    before_cut += std::abs(cut.samples[i]);
    before_loop += std::abs(looped.samples[i]);
  }
  for (std::size_t i = 0; i < 4800; ++i) cards += std::abs(looped.samples[i]);
  EXPECT_EQ(before_cut, 0.0);
  EXPECT_GT(before_loop, 1.0) << "the tail past the end plays at the loop's start";
  EXPECT_EQ(cards, 0.0) << "nothing wraps into the title cards";
}

TEST(Mix, MurmurFillsItsWindowWithItsShapeAndBreathFollowsTheFlow) {
  MixRequest r;
  r.duration_s = 1.0;
  r.murmur.gain = 1;
  r.murmur.shape = MurmurShape::kDecrescendo;
  r.murmur.windows = {{0.2, 0.6}};
  const Soundtrack m = mix(r);
  const auto energy = [&](double from, double to) {
    double e = 0;
    for (auto i = std::size_t(from * kSampleRateHz); i < std::size_t(to * kSampleRateHz); ++i) e += double(m.samples[i]) * m.samples[i];
    return e;
  };
  EXPECT_EQ(energy(0.0, 0.2), 0.0);
  EXPECT_EQ(energy(0.6, 1.0), 0.0);
  EXPECT_GT(energy(0.22, 0.3), 4 * energy(0.5, 0.58)) << "decrescendo: loudest at its start";
  EXPECT_NEAR(murmur_envelope(MurmurShape::kDiamond, 0.5, 1), 1.0, 1e-12);
  EXPECT_NEAR(murmur_envelope(MurmurShape::kCrescendo, 0.25, 1), 0.25, 1e-12);

  MixRequest b;
  b.duration_s = 1.0;
  b.breath.gain = 1;
  b.breath.flow = {{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}};
  const Soundtrack br = mix(b);
  double early = 0, middle = 0;
  for (std::size_t i = 0; i < 4800; ++i) early += std::abs(br.samples[i]);
  for (std::size_t i = 21600; i < 26400; ++i) middle += std::abs(br.samples[i]);
  EXPECT_GT(middle, 5 * early) << "louder where the air flows fastest";
}

TEST(Wav, HeaderAndSamplesAreWhatTheySay) {
  Soundtrack t;
  t.samples = {0.0f, 0.5f, -1.0f, 2.0f};
  const std::string w = wav_bytes(t);
  ASSERT_EQ(w.size(), 44u + 8u);
  EXPECT_EQ(w.substr(0, 4), "RIFF");
  EXPECT_EQ(w.substr(8, 8), "WAVEfmt ");
  EXPECT_EQ(w.substr(36, 4), "data");
  std::uint32_t rate = 0;
  std::memcpy(&rate, w.data() + 24, 4);
  EXPECT_EQ(rate, 48000u);
  std::int16_t s[4];
  std::memcpy(s, w.data() + 44, 8);
  EXPECT_EQ(s[1], 16384);
  EXPECT_EQ(s[2], -32767);
  EXPECT_EQ(s[3], 32767) << "clamped, not wrapped";
  const auto dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / "wav";
  std::filesystem::create_directories(dir);
  write_wav(dir / "t.wav", t);
  std::ifstream in(dir / "t.wav", std::ios::binary);
  std::stringstream back;
  back << in.rdbuf();
  EXPECT_EQ(back.str(), w);
}

}  // namespace
}  // namespace systole::audio
