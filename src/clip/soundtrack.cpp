#include "clip/soundtrack.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "sim/constraints/volume.h"

namespace systole::clip {
namespace {

int organ_index(const scene::Scene& scene, const std::string& name) {
  for (std::size_t o = 0; o < scene.organs.size(); ++o)
    if (scene.organs[o].name == name) return static_cast<int>(o);
  return -1;
}

audio::MurmurShape murmur_shape(scene::MurmurShape s) {
  switch (s) {
    case scene::MurmurShape::kPlateau: return audio::MurmurShape::kPlateau;
    case scene::MurmurShape::kDecrescendo: return audio::MurmurShape::kDecrescendo;
    case scene::MurmurShape::kCrescendo: return audio::MurmurShape::kCrescendo;
    default: return audio::MurmurShape::kDiamond;
  }
}

/// The stethoscope's weighting of each heart sound (unit: 1). At the apex S1 is louder than
/// S2 and S3 is heard best; at the base S2 is louder than S1 (Bates' Guide, ch. 9).
double site_weight(scene::Stethoscope site, audio::SoundKind kind) {
  const bool apex = site == scene::Stethoscope::kApex;
  switch (kind) {
    case audio::SoundKind::kS1: return apex ? 1.0 : 0.5;
    case audio::SoundKind::kS2: return apex ? 0.55 : 1.0;
    case audio::SoundKind::kS3: return apex ? 1.0 : 0.35;
    default: return 1.0;
  }
}

/// The murmur and its windows in video time: between `from` and `to` of the way from each
/// event that opens its phase (S1 for a systolic murmur) in the clip to the next that closes it.
audio::MurmurSound murmur(const scene::Murmur& m, const std::vector<world::CycleEvent>& events, const ClipClock& clock,
                     const std::function<bool(double organ_s)>& in_clip) {
  const bool systolic = m.phase == scene::MurmurPhase::kSystolic;
  const auto opens = systolic ? world::CycleEventKind::kSystoleStart : world::CycleEventKind::kSystoleEnd;
  const auto closes = systolic ? world::CycleEventKind::kSystoleEnd : world::CycleEventKind::kSystoleStart;
  audio::MurmurSound out;
  out.shape = murmur_shape(m.shape);
  out.pitch_hz = m.pitch_hz;
  out.gain = audio::gain_of_db(m.level_db);
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].kind != opens || !in_clip(events[i].time_s)) continue;
    for (std::size_t j = i + 1; j < events.size(); ++j) {
      if (events[j].kind == opens) break;
      if (events[j].kind != closes) continue;
      const double t0 = clock.video_s(events[i].time_s), t1 = clock.video_s(events[j].time_s);
      out.windows.push_back({t0 + m.from * (t1 - t0), t0 + m.to * (t1 - t0)});
      break;
    }
  }
  return out;
}

}  // namespace

SoundProbe::SoundProbe(const scene::Scene& scene, const world::World& world) {
  const scene::Audio& a = scene.audio;
  if (a.heart.enabled) {
    heart_organ_ = organ_index(scene, a.heart.organ);
    std::vector<int> regions;
    const scene::Organ& organ = scene.organs[static_cast<std::size_t>(heart_organ_)];
    for (std::size_t r = 0; r < organ.regions.size(); ++r)
      if (std::find(a.heart.regions.begin(), a.heart.regions.end(), organ.regions[r].name) != a.heart.regions.end())
        regions.push_back(static_cast<int>(r));
    const sim::Model& model = world.organs[static_cast<std::size_t>(heart_organ_)].model;
    ventricles_ = world::RegionSize(model, regions);
    for (std::size_t c = 0; c < model.circulation.chambers.size(); ++c) {
      if (model.circulation.chambers[c].name == "left_ventricle") left_ventricle_ = static_cast<int>(c);
    }
  }
  if (a.breath.enabled) breath_organ_ = organ_index(scene, a.breath.organ);
}

void SoundProbe::record(int organ, const world::OrganBody& body) {
  if (organ == heart_organ_) {
    if (left_ventricle_ >= 0) record_valve_closure(body);
    size_.push_back({body.state.time_s, ventricles_.measure(body.state.x)});
  }
  if (organ == breath_organ_ && body.model.volume.enabled)
    volume_.push_back({body.state.time_s, sim::enclosed_volume(body.state.x, body.model.volume.triangles)});
}

void SoundProbe::record_valve_closure(const world::OrganBody& body) {
  const sim::ChamberPhase phase = body.state.chambers[static_cast<std::size_t>(left_ventricle_)].phase;
  if (phase == left_phase_) return;
  left_phase_ = phase;
  // The phase changed during the step that just ended: its middle, as validate --physiology
  // times the valves.
  const double t = body.state.time_s, at = size_.empty() ? t : 0.5 * (size_.back().time_s + t);
  if (phase == sim::ChamberPhase::kIsovolumicContraction) valve_closures_.push_back({world::CycleEventKind::kSystoleStart, at});
  if (phase == sim::ChamberPhase::kIsovolumicRelaxation) valve_closures_.push_back({world::CycleEventKind::kSystoleEnd, at});
}

SoundSources SoundProbe::finish() const {
  SoundSources s;
  s.ventricle_size = size_;
  s.events = world::detect_cycle_events(size_);
  if (left_ventricle_ >= 0) {
    // With blood S1 and S2 are the valves' closures; S3 stays the peak of early refilling.
    std::erase_if(s.events, [](const world::CycleEvent& e) { return e.kind != world::CycleEventKind::kPeakRefill; });
    s.events.insert(s.events.end(), valve_closures_.begin(), valve_closures_.end());
    std::sort(s.events.begin(), s.events.end(),
              [](const world::CycleEvent& a, const world::CycleEvent& b) { return a.time_s < b.time_s; });
  }
  s.breath_volume = volume_;
  return s;
}

ClipClock clip_clock(const scene::Scene& scene, int first_frame, int card_frames) {
  ClipClock c;
  c.frame_s = scene.output.frame_period_s();
  c.fps = scene.output.fps;
  c.organ_start_s = scene.output.organ_time_s(first_frame);
  c.cards_s = first_frame == 0 ? card_frames / c.fps : 0.0;
  return c;
}

audio::MixRequest mix_request(const scene::Scene& scene, const SoundSources& src, const ClipClock& clock,
                              double duration_s, bool loop) {
  const scene::Audio& a = scene.audio;
  audio::MixRequest r;
  r.duration_s = duration_s;
  r.loop_from_s = loop ? clock.cards_s : -1;
  r.seed = scene.seed;
  r.master_gain = audio::gain_of_db(a.level_db);
  // A loop hears the events of one period, each once (its tail wraps); a clip hears the
  // events up to half a second before its start too, which ring into it.
  const double organ_end_s = clock.organ_start_s + (duration_s - clock.cards_s) * clock.fps * clock.frame_s;
  const double organ_from_s = loop ? clock.organ_start_s : clock.organ_start_s - 0.5;
  const auto in_clip = [&](double organ_s) { return organ_s >= organ_from_s && organ_s < organ_end_s; };
  if (a.heart.enabled) {
    const scene::HeartAudio& h = a.heart;
    for (const world::CycleEvent& e : src.events) {
      if (!in_clip(e.time_s)) continue;
      const scene::HeartTone& tone = e.kind == world::CycleEventKind::kSystoleStart ? h.s1
                                     : e.kind == world::CycleEventKind::kSystoleEnd ? h.s2
                                                                                    : h.s3;
      if (!tone.enabled) continue;
      const audio::SoundKind kind = e.kind == world::CycleEventKind::kSystoleStart ? audio::SoundKind::kS1
                                    : e.kind == world::CycleEventKind::kSystoleEnd ? audio::SoundKind::kS2
                                                                                   : audio::SoundKind::kS3;
      r.events.push_back({kind, clock.video_s(e.time_s), site_weight(h.stethoscope, kind) * audio::gain_of_db(tone.level_db)});
    }
    if (h.murmur.enabled) r.murmur = murmur(h.murmur, src.events, clock, in_clip);
  }
  if (a.breath.enabled) {
    r.breath.gain = audio::gain_of_db(a.breath.level_db);
    const auto& v = src.breath_volume;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      const double flow = (v[i + 1].value - v[i - 1].value) / (v[i + 1].time_s - v[i - 1].time_s);
      r.breath.flow.push_back({clock.video_s(v[i].time_s), flow});
    }
  }
  if (a.click.enabled) {
    // Clicks on the teaching rate in organ time from the clip's first frame, so they slow down with the clip.
    const double period = 1.0 / a.click.rate_hz;
    for (int k = 0;; ++k) {
      const double organ_s = clock.organ_start_s + a.click.start_s + k * period;
      if (organ_s >= organ_end_s - 1e-9) break;
      r.events.push_back({audio::SoundKind::kClick, clock.video_s(organ_s), audio::gain_of_db(a.click.level_db)});
    }
  }
  return r;
}

audio::Soundtrack make_soundtrack(const scene::Scene& scene, world::FrameSource& source, const std::vector<int>& frames,
                                  int card_frames) {
  const int first_frame = frames.front(), last_frame = frames.back();
  const ClipClock clock = clip_clock(scene, first_frame, card_frames);
  const double duration_s = clock.cards_s + (last_frame - first_frame + 1) / clock.fps;
  const bool loop = scene.output.loop && first_frame == 0 && last_frame + 1 == scene.output.frame_count();
  // Past the last frame: a turn is known once the size has moved back from it (half a
  // second confirms the last S1 or S2 of the clip); a loop's last murmur window closes within
  // a second.
  const int extra = static_cast<int>(std::ceil((loop ? 1.0 : 0.5) / source.world().frame_s));
  // Shared with the hook, which the source keeps after this returns (replays call no step hook).
  const auto probe = std::make_shared<SoundProbe>(scene, source.world());
  const world::StepHook listen = [probe](int organ, const world::OrganBody& body) { probe->record(organ, body); };
  if (source.replays_bake()) {
    world::FrameSource own(scene);
    own.on_step(listen);
    own.advance_to(last_frame + extra);
  } else {
    source.on_step(listen);
    source.simulate_ahead(last_frame + extra, frames);
  }
  return audio::mix(mix_request(scene, probe->finish(), clock, duration_s, loop));
}

}  // namespace systole::clip
