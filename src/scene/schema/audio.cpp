// The audio table (docs/sound.md): heart sounds, breath sounds, a click.

#include <algorithm>

#include "scene/schema/parts.h"

namespace systole::scene::schema {
namespace {

ValueSpec<HeartTone> tone_spec(const std::string& what) {
  return map<HeartTone>(
      {
          field("enabled", boolean(), &HeartTone::enabled, "Play " + what + "."),
          field("level", quantity(Dimension::kLevel, closed(-60, 12)), &HeartTone::level_db,
                "Loudness relative to the model's (0 dB)."),
      });
}

ValueSpec<Murmur> murmur_spec() {
  return map<Murmur>(
      {
          field("shape",
                choice<MurmurShape>({{"diamond", MurmurShape::kDiamond},
                                     {"plateau", MurmurShape::kPlateau},
                                     {"decrescendo", MurmurShape::kDecrescendo},
                                     {"crescendo", MurmurShape::kCrescendo}}),
                &Murmur::shape,
                "Loudness over the window: diamond (crescendo-decrescendo, aortic stenosis), plateau (holosystolic, "
                "mitral regurgitation), decrescendo (aortic regurgitation), crescendo."),
          field("phase", choice<MurmurPhase>({{"systolic", MurmurPhase::kSystolic}, {"diastolic", MurmurPhase::kDiastolic}}),
                &Murmur::phase, "systolic: between S1 and S2; diastolic: between S2 and the next S1 (simulated times)."),
          field("from", number(closed(0, 1)), &Murmur::from, "Start of the window as a fraction of the phase."),
          field("to", number(closed(0, 1)), &Murmur::to, "End of the window as a fraction of the phase (after from)."),
          field("pitch", quantity(Dimension::kFrequency, closed(40, 1000)), &Murmur::pitch_hz,
                "Centre of the murmur's noise band (harsh ejection murmurs about 150 Hz, blowing regurgitant ones "
                "higher)."),
          field("level", quantity(Dimension::kLevel, closed(-60, 12)), &Murmur::level_db, "Loudness."),
      },
      [](const Node& node, Murmur& m, const std::string& path, const Context&) {
        if (m.to <= m.from)
          fail(origin_of(node, "to"), join(path, "to"),
               format_number(m.to) + " must be after from (" + format_number(m.from) + ")");
        m.enabled = true;
        m.origin = node.origin;
      });
}

ValueSpec<HeartAudio> heart_spec() {
  ValueSpec<std::vector<std::string>> regions;
  const ValueSpec<std::string> name = name_text();
  regions.type = "list of names";
  regions.range = "1..16 region names";
  regions.read = [name](const Node& node, std::vector<std::string>& out, const std::string& path, const Context& ctx) {
    out.clear();
    if (node.kind != Node::Kind::kList || node.items.empty() || node.items.size() > 16)
      fail(node.origin, path, "expected a list of region names, e.g. [left_ventricle, right_ventricle]; got " + node.describe());
    for (std::size_t i = 0; i < node.items.size(); ++i) {
      std::string n;
      name.read(node.items[i], n, path + "[" + std::to_string(i) + "]", ctx);
      out.push_back(n);
    }
  };
  regions.show = [](const std::vector<std::string>&) { return std::string("every region named *ventric*"); };
  return map<HeartAudio>(
      {
          field("organ", name_text(), &HeartAudio::organ, "The heart whose ventricles time the sounds.")
              .shown_default("the first organ with a ventricular region"),
          field("regions", regions, &HeartAudio::regions,
                "The ventricular regions whose simulated size times S1 (they start to shrink) and S2 (they start to "
                "refill)."),
          field("stethoscope", choice<Stethoscope>({{"apex", Stethoscope::kApex}, {"base", Stethoscope::kBase}}),
                &HeartAudio::stethoscope, "Where the stethoscope rests: apex (S1 louder) or base (S2 louder)."),
          field("s1", tone_spec("S1"), &HeartAudio::s1,
                "First heart sound (mitral and tricuspid closure) when the ventricles start to shrink.")
              .shown_default("on, 0 dB"),
          field("s2", tone_spec("S2"), &HeartAudio::s2,
                "Second heart sound (aortic and pulmonary closure) when the ventricles start to refill.")
              .shown_default("on, 0 dB"),
          field("s3", tone_spec("S3"), &HeartAudio::s3,
                "Third heart sound (a low thud as rapid filling stops) at the simulated peak of early refilling; off "
                "unless given (`s3: {}` turns it on, at -6 dB unless it sets a level).")
              .shown_default("off"),
          field("murmur", murmur_spec(), &HeartAudio::murmur, "Filtered noise over a window of systole or diastole.")
              .shown_default("none"),
      },
      [](const Node& node, HeartAudio& h, const std::string&, const Context&) {
        h.enabled = true;
        // `s3:` given means it is wanted unless it says enabled: false.
        if (const Node* s3 = node.find("s3"); s3 != nullptr && !s3->find("enabled")) h.s3.enabled = true;
        h.origin = node.origin;
      });
}

}  // namespace

ValueSpec<Audio> audio_spec() {
  auto breath = map<BreathAudio>(
      {
          field("organ", name_text(), &BreathAudio::organ, "The lungs whose simulated volume flow the sound follows.")
              .shown_default("the first organ with a volume drive"),
          field("level", quantity(Dimension::kLevel, closed(-60, 12)), &BreathAudio::level_db, "Loudness."),
      },
      [](const Node& node, BreathAudio& b, const std::string&, const Context&) {
        b.enabled = true;
        b.origin = node.origin;
      });
  auto click = map<ClickAudio>(
      {
          field("rate", quantity(Dimension::kFrequency, open_closed(0, 10)), &ClickAudio::rate_hz,
                "Clicks per second of organ time (slowed with output.slow_motion), e.g. 60 bpm.")
              .required(),
          field("start", quantity(Dimension::kTime, closed(0, 3600)), &ClickAudio::start_s,
                "First click, in organ time from the clip's first frame."),
          field("level", quantity(Dimension::kLevel, closed(-60, 12)), &ClickAudio::level_db, "Loudness."),
      },
      [](const Node& node, ClickAudio& c, const std::string&, const Context&) {
        c.enabled = true;
        c.origin = node.origin;
      });
  return map<Audio>(
      {
          field("level", quantity(Dimension::kLevel, closed(-60, 0)), &Audio::level_db,
                "Master gain of the mix (the mix is then limited to full scale)."),
          field("heart", heart_spec(), &Audio::heart, "Heart sounds timed by the simulated ventricles.")
              .shown_default("none"),
          field("breath", breath, &Audio::breath, "Breath sounds following a lung's simulated volume flow.")
              .shown_default("none"),
          field("click", click, &Audio::click, "A metronome click at a teaching rate.").shown_default("none"),
      },
      [](const Node& node, Audio& a, const std::string& path, const Context&) {
        if (!a.heart.enabled && !a.breath.enabled && !a.click.enabled)
          fail(node.origin, path, "says nothing to play: give heart, breath or click");
        a.enabled = true;
        a.origin = node.origin;
      });
}

void check_audio(const Node& root, Scene& s) {
  const Node* node = root.find("audio");
  if (!node || !s.audio.enabled) return;
  auto find_organ = [&](const std::string& name, const Origin& origin, const std::string& path) -> Organ* {
    for (Organ& o : s.organs)
      if (o.name == name) return &o;
    fail(origin, path, "no organ is named '" + name + "'");
    return nullptr;
  };
  const auto ventricular = [](const std::string& name) { return name.find("ventric") != std::string::npos; };
  HeartAudio& h = s.audio.heart;
  if (h.enabled) {
    const Node* heart = node->find("heart");
    Organ* organ = nullptr;
    if (!h.organ.empty()) {
      organ = find_organ(h.organ, origin_of(*heart, "organ"), "audio.heart.organ");
    } else {
      for (Organ& o : s.organs)
        if (!organ && std::any_of(o.regions.begin(), o.regions.end(), [&](const Region& r) { return ventricular(r.name); }))
          organ = &o;
      if (!organ)
        fail(heart->origin, "audio.heart",
             "no organ has a region named like a ventricle; name the organ (audio.heart.organ) and its regions "
             "(audio.heart.regions)");
      h.organ = organ->name;
    }
    if (h.regions.empty()) {
      for (const Region& r : organ->regions)
        if (ventricular(r.name)) h.regions.push_back(r.name);
      if (h.regions.empty())
        fail(origin_of(*heart, "organ"), "audio.heart.regions",
             "organ '" + organ->name + "' has no region named like a ventricle; list the regions whose size times S1 and S2");
    }
    for (std::size_t i = 0; i < h.regions.size(); ++i) {
      const auto r = std::find_if(organ->regions.begin(), organ->regions.end(),
                                  [&](const Region& x) { return x.name == h.regions[i]; });
      const Node* list = heart->find("regions");
      const Origin& where = list ? list->items[i].origin : heart->origin;
      const std::string path = "audio.heart.regions[" + std::to_string(i) + "]";
      if (r == organ->regions.end())
        fail(where, path, "organ '" + organ->name + "' has no region named '" + h.regions[i] + "'");
      if (r->pinned) fail(where, path, "region '" + r->name + "' is pinned: it never contracts, so it times no sound");
    }
  }
  BreathAudio& b = s.audio.breath;
  if (b.enabled) {
    const Node* breath = node->find("breath");
    if (!b.organ.empty()) {
      find_organ(b.organ, origin_of(*breath, "organ"), "audio.breath.organ");
    } else {
      for (const Organ& o : s.organs)
        if (b.organ.empty() && o.body.volume_drive.waveform != Waveform::kNone) b.organ = o.name;
      if (b.organ.empty())
        fail(breath->origin, "audio.breath",
             "no organ's body has a volume_drive (breathing lungs); name the organ (audio.breath.organ)");
    }
  }
}

}  // namespace systole::scene::schema
