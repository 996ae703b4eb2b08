#pragma once
// A soundtrack from timed sound events (docs/sound.md). Pure: no simulation, no libav; the
// caller (clip/soundtrack.h) measures the events on the simulation and places them in video
// time. Mono, 48 kHz (the one rate AAC, Opus and FLAC all take), float in [-1, 1].

#include <cstdint>
#include <vector>

namespace systole::audio {

inline constexpr int kSampleRateHz = 48000;

enum class SoundKind { kS1, kS2, kS3, kClick };

/// One short sound, starting at time_s.
struct SoundEvent {
  SoundKind kind = SoundKind::kS1;
  double time_s = 0;  ///< Video time of the sound's onset. unit: s
  double gain = 1;    ///< Amplitude factor (stethoscope weighting and level). unit: 1
};

enum class MurmurShape { kDiamond, kPlateau, kDecrescendo, kCrescendo };

/// A murmur over [from_s, to_s) of video time.
struct MurmurWindow {
  double from_s = 0, to_s = 0;  ///< unit: s
};

struct MurmurSound {
  MurmurShape shape = MurmurShape::kDiamond;
  double pitch_hz = 180;  ///< Centre of the noise band. unit: Hz
  double gain = 0;        ///< unit: 1; 0: none
  std::vector<MurmurWindow> windows;
};

/// Air flow into an organ, sampled in video time (uniform or not; linearly interpolated).
struct FlowSample {
  double time_s = 0;  ///< Video time. unit: s
  double flow = 0;    ///< Volume change per organ second; positive: inspiration. unit: m^3/s
};

struct BreathSound {
  double gain = 0;  ///< unit: 1; 0: none
  std::vector<FlowSample> flow;
};

struct MixRequest {
  double duration_s = 0;     ///< The soundtrack's length (the video's). unit: s
  double loop_from_s = -1;   ///< >= 0: [loop_from_s, duration_s) is a loop; sounds ringing past its end wrap to its start. unit: s
  std::uint64_t seed = 1;
  double master_gain = 1;    ///< unit: 1
  std::vector<SoundEvent> events;
  MurmurSound murmur;
  BreathSound breath;
};

struct Soundtrack {
  int sample_rate_hz = kSampleRateHz;
  std::vector<float> samples;  ///< Mono. unit: full scale
  double duration_s() const { return static_cast<double>(samples.size()) / sample_rate_hz; }
};

/// Samples of a soundtrack `duration_s` long: round(duration_s * rate). unit: samples
std::int64_t sample_count(double duration_s, int sample_rate_hz = kSampleRateHz);

/// Synthesizes every sound of `request` and mixes them (sounds that would ring past the end
/// of a loop wrap to its start, so the loop is seamless; elsewhere past the end is cut).
Soundtrack mix(const MixRequest& request);

/// dB to an amplitude factor: 10^(dB / 20). unit: 1
double gain_of_db(double level_db);

}  // namespace systole::audio
