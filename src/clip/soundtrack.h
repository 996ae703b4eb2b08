#pragma once
// The clip's soundtrack (docs/sound.md): the simulation measured after every solver step
// (world/sound_sources.h) gives the events, which are placed in video time and synthesized
// by audio/. The video's frames arrive in order while the sound of a frame can depend on
// what happens after it (a murmur ends at the next S2, a loop's last sound rings into its
// first frame), so the soundtrack is made before the frames: it listens to the clip's own
// frame source, which simulates ahead through the clip and then replays the frames it kept
// (world/frame_source.h): one run of the simulation for the sound and the pictures.

#include <vector>

#include "audio/soundtrack.h"
#include "scene/scene.h"
#include "sim/circulation.h"
#include "world/sound_sources.h"
#include "world/frame_source.h"
#include "world/world.h"

namespace systole::clip {

/// What the soundtrack reads from one run of the simulation, in organ time.
struct SoundSources {
  std::vector<world::Sample> ventricle_size;  ///< audio.heart's regions, every step. unit: m
  /// S1, S2 and S3 instants: the size's turning points (with blood, S1 and S2 the valves').
  std::vector<world::CycleEvent> events;
  std::vector<world::Sample> breath_volume;   ///< audio.breath's organ, every step. unit: m^3
};

/// Measures the scene's sound sources on a world as it is stepped: record() after every
/// solver step (a world::StepHook), then finish().
class SoundProbe {
 public:
  SoundProbe(const scene::Scene& scene, const world::World& world);
  /// Takes the sample of organ `organ` after its step.
  void record(int organ, const world::OrganBody& body);
  /// The samples so far and the events they show.
  SoundSources finish() const;

 private:
  void record_valve_closure(const world::OrganBody& body);

  int heart_organ_ = -1, breath_organ_ = -1;
  world::RegionSize ventricles_;
  std::vector<world::Sample> size_, volume_;
  /// With blood: the left ventricle's chamber, its phase after the last step, and the
  /// closures of its valves (S1 the mitral, S2 the aortic).
  int left_ventricle_ = -1;
  sim::ChamberPhase left_phase_ = sim::ChamberPhase::kFilling;
  std::vector<world::CycleEvent> valve_closures_;
};

/// How organ time maps to the video: frame k of the clip shows organ time
/// (start_frame + k) * frame_s and is shown at video time k / fps, after the title cards
/// when the video starts at the clip's start.
struct ClipClock {
  double organ_start_s = 0;  ///< Organ time of the video's first clip frame. unit: s
  double frame_s = 1.0 / 30; ///< Organ time between frames. unit: s
  double fps = 30;           ///< unit: 1/s
  double cards_s = 0;        ///< Title cards before the clip. unit: s
  /// Video time of organ time t. unit: s
  double video_s(double organ_s) const { return cards_s + (organ_s - organ_start_s) / frame_s / fps; }
};

/// The clock of a video of clip frames [first_frame, ...], with `card_frames` of title cards
/// before it (only when first_frame is 0).
ClipClock clip_clock(const scene::Scene& scene, int first_frame, int card_frames);

/// The mix the scene asks for from measured sources, for a video `duration_s` long (with
/// `loop`, the clip after the cards is a seamless loop).
audio::MixRequest mix_request(const scene::Scene& scene, const SoundSources& sources, const ClipClock& clock,
                              double duration_s, bool loop);

/// The soundtrack of a video of clip `frames` (consecutive, or a selection whose first and
/// last bound the video) with `card_frames` of title cards. Listens to `source` while it
/// simulates ahead through the last frame and half a second more (a second for a loop, so its
/// last murmur window closes; the clip's last turns are confirmed), keeping `frames` for the
/// pictures to replay; then mixes. A source that replays a bake has no steps to hear: the
/// sound then runs a source of its own.
audio::Soundtrack make_soundtrack(const scene::Scene& scene, world::FrameSource& source, const std::vector<int>& frames,
                                  int card_frames);

}  // namespace systole::clip
