// ctest-labels: slow-under-sanitizers
// The soundtrack and text tracks of a rendered clip (docs/sound.md): heart sounds land where
// the simulated ventricles turn (measured here independently, from the particles'
// velocities every step), irregular beats sound irregular, the video carries AAC / Opus /
// FLAC and a subtitle track whose cues are the captions, the sound lasts as long as the
// pictures, and --wav writes the soundtrack alone.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "clip/render_clip.h"
#include "clip/text_tracks.h"
#include "encode/png.h"
#include "scene/load.h"
#include "support/run.h"
#include "support/small_heart_clip.h"
#include "world/world.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

bool have(const char* tool) { return run(std::string("command -v ") + tool).exit_code == 0; }


const std::string kTracks =
    "audio: {heart: {s3: {}, murmur: {shape: diamond}}, click: {rate: 60 bpm}}\n"
    "cards:\n  - {text: \"Title\\nsub\", duration: 0.5 s, fade: 0.1 s}\n"
    "captions:\n  - {text: \"First words\", from: 0.1 s, to: 0.6 s, fade: 0.1 s}\n  - {text: \"Then more\", from: 0.8 s, to: 1.2 s, fade: 0.1 s}\n"
    "chapters:\n  - {title: \"Beat\", at: 0.4 s}\n";

/// Mono float samples of a file's first audio stream at 48 kHz, decoded by ffmpeg (which
/// honours the edit list / codec delay: the encoder's priming is dropped).
std::vector<float> decode_audio(const fs::path& file) {
  const fs::path raw = file.string() + ".f32";
  run("ffmpeg -v error -y -i " + file.string() + " -map 0:a:0 -f f32le -ac 1 -ar 48000 " + raw.string());
  const std::string bytes = read_file(raw);
  std::vector<float> x(bytes.size() / 4);
  std::memcpy(x.data(), bytes.data(), x.size() * 4);
  return x;
}

std::vector<float> read_wav(const fs::path& file) {
  const std::string bytes = read_file(file);
  std::vector<float> x;
  for (std::size_t i = 44; i + 1 < bytes.size(); i += 2) {
    std::int16_t s;
    std::memcpy(&s, bytes.data() + i, 2);
    x.push_back(s / 32767.0f);
  }
  return x;
}

/// Sound onsets: the first sample above `share` of the peak after at least 20 ms below it. unit: s
std::vector<double> onsets(const std::vector<float>& x, double share = 0.05) {
  double peak = 0;
  for (float v : x) peak = std::max(peak, std::abs(double(v)));
  const double threshold = share * peak;
  std::vector<double> t;
  std::size_t quiet = 48000;  // Samples since the last loud one.
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::abs(double(x[i])) >= threshold) {
      if (quiet >= 960) t.push_back(double(i) / 48000);
      quiet = 0;
    } else {
      ++quiet;
    }
  }
  return t;
}

struct Turn {
  bool shrink;    ///< true: the ventricles start to shrink (S1); false: to refill (S2).
  double time_s;  ///< Organ time.
  /// Other turns of the same kind as extreme as this one within a thousandth of the size's
  /// range, a ripple between them: a plateau, which of them times the sound is a tie.
  std::vector<double> ties_s = {};
};

/// The ventricles' turning points measured here, not by the code that placed the sounds:
/// the mean radial velocity of the regions' particles about their centroid (from the
/// velocities the solver keeps, not from differences of sizes) changes sign, interpolated
/// linearly between steps; a turn counts when the size then swings by over 30 % of its range.
/// Simulates half a second past `frames` so the clip's last turn is confirmed by what follows.
std::vector<Turn> simulated_turns(const scene::Scene& s, const std::vector<std::string>& regions, int frames) {
  world::World w = world::build_world(s);
  std::vector<int> particles;
  const auto& model = w.organs[0].model;
  for (int p = 0; p < model.particle_count(); ++p) {
    const int r = model.vertex_region[static_cast<std::size_t>(p)];
    if (r >= 0 && std::find(regions.begin(), regions.end(), s.organs[0].regions[static_cast<std::size_t>(r)].name) != regions.end())
      particles.push_back(p);
  }
  struct Step {
    double t, radial, size;
  };
  std::vector<Step> steps;
  w.after_step = [&](int organ, const world::OrganBody& b) {
    if (organ != 0) return;
    Eigen::Vector3d c = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
    for (int p : particles) {
      c += b.state.x.col(p);
      v += b.state.v.col(p);
    }
    c /= particles.size();
    v /= particles.size();
    double radial = 0, size = 0;
    for (int p : particles) {
      const Eigen::Vector3d d = b.state.x.col(p) - c;
      radial += d.dot(b.state.v.col(p) - v) / d.norm();
      size += d.norm();
    }
    steps.push_back({b.state.time_s, radial / particles.size(), size / particles.size()});
  };
  world::advance_to_frame(w, frames + static_cast<int>(std::ceil(0.5 / w.frame_s)));
  double lo = 1e9, hi = -1e9;
  for (const Step& st : steps) lo = std::min(lo, st.size), hi = std::max(hi, st.size);
  std::vector<Turn> all;
  std::vector<double> sizes;
  for (std::size_t i = 1; i < steps.size(); ++i) {
    const Step &a = steps[i - 1], &b = steps[i];
    if ((a.radial > 0) == (b.radial > 0)) continue;
    const double u = a.radial / (a.radial - b.radial);
    all.push_back({a.radial > 0, a.t + u * (b.t - a.t)});
    sizes.push_back(a.size);
  }
  std::vector<Turn> kept;
  std::vector<double> kept_size;
  // The turns of the whole run; the caller keeps those inside its clip.
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!kept.empty() && kept.back().shrink == all[i].shrink) {
      // The same kind again: keep the more extreme one, and on a plateau (the two within a
      // thousandth of the range: heart-afib has a beat whose two maxima are 4e-8 m apart,
      // a 0.04-mm ripple between them) both, as a tie.
      const bool tie = std::abs(sizes[i] - kept_size.back()) <= 1e-3 * (hi - lo);
      std::vector<double> ties = kept.back().ties_s;
      if (tie) ties.push_back(kept.back().time_s);
      if ((all[i].shrink && sizes[i] > kept_size.back()) || (!all[i].shrink && sizes[i] < kept_size.back())) {
        kept.back() = all[i];
        kept_size.back() = sizes[i];
      } else if (tie) {
        ties.back() = all[i].time_s;
      }
      kept.back().ties_s = ties;
      continue;
    }
    if (!kept.empty() && std::abs(sizes[i] - kept_size.back()) < 0.3 * (hi - lo)) continue;
    kept.push_back(all[i]);
    kept_size.push_back(sizes[i]);
  }
  return kept;
}

/// With blood, S1 and S2 are the left ventricle's valves closing: its phase leaving filling
/// (the mitral valve shuts) and leaving ejection (the aortic valve shuts), each at the middle
/// of the step in which it changed, from a pass over the simulation of this test's own.
std::vector<Turn> valve_closures(const scene::Scene& s, int frames) {
  world::World w = world::build_world(s);
  const auto& chambers = w.organs[0].model.circulation.chambers;
  std::size_t lv = chambers.size();
  for (std::size_t c = 0; c < chambers.size(); ++c) {
    if (chambers[c].name == "left_ventricle") lv = c;
  }
  std::vector<Turn> closures;
  if (lv == chambers.size()) return closures;
  sim::ChamberPhase last = sim::ChamberPhase::kFilling;
  double last_t = 0;
  w.after_step = [&](int organ, const world::OrganBody& b) {
    if (organ != 0) return;
    const sim::ChamberPhase phase = b.state.chambers[lv].phase;
    const double mid = 0.5 * (last_t + b.state.time_s);
    if (phase != last && phase == sim::ChamberPhase::kIsovolumicContraction) closures.push_back({true, mid});
    if (phase != last && phase == sim::ChamberPhase::kIsovolumicRelaxation) closures.push_back({false, mid});
    last = phase;
    last_t = b.state.time_s;
  };
  world::advance_to_frame(w, frames);
  return closures;
}

// The shipped auscultation scene's heart has blood: its S1 and S2 are the mitral and aortic
// valves closing, the instants validate --physiology prints.
TEST(Sound, AuscultationOnsetsLandWithin10MsOfTheValvesClosing) {
  if (!have("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed: cannot decode the video's sound";
  const fs::path dir = scratch("auscultation");
  const std::string scene_file = source("scenes/heart-auscultation.yaml");
  const fs::path video = dir / "a.mp4";
  const auto r = run(systole() + " render " + scene_file + " -D output.width=320 -D output.height=180 -o " + video.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const scene::Scene s = scene::load(scene_file);
  const double cards_s = clip::card_frame_counts(s)[0] / s.output.fps;
  ASSERT_TRUE(s.organs[0].blood.enabled);
  const std::vector<Turn> turns = valve_closures(s, s.output.frame_count() - 1);
  const std::vector<double> heard = onsets(decode_audio(video));
  ASSERT_GE(turns.size(), 20u);  // 12 beats in 10 s, each a mitral and an aortic closure.
  int checked = 0;
  double worst = 0;
  for (const Turn& turn : turns) {
    if (turn.time_s < 0.1 || turn.time_s > s.output.duration_s - 0.1) continue;
    const double at = cards_s + turn.time_s;
    double nearest = 1e9;
    for (double h : heard) nearest = std::abs(h - at) < std::abs(nearest) ? h - at : nearest;
    EXPECT_LE(std::abs(nearest), 0.010) << (turn.shrink ? "S1" : "S2") << " at organ time " << turn.time_s
                                        << " s: nearest onset " << 1e3 * nearest << " ms away";
    worst = std::max(worst, std::abs(nearest));
    ++checked;
  }
  EXPECT_GE(checked, 20);
  std::cout << "[ measured ] " << checked << " S1/S2 onsets, worst " << 1e3 * worst << " ms from the valve's closing\n";
  // Every onset heard is an S1 or S2 (or the S3 that follows an S2 within 400 ms).
  for (double h : heard) {
    bool explained = false;
    for (const Turn& turn : turns) {
      const double at = cards_s + turn.time_s;
      explained = explained || std::abs(h - at) <= 0.010 || (!turn.shrink && h > at && h < at + 0.4);
    }
    EXPECT_TRUE(explained) << "an onset at " << h << " s belongs to no heart sound";
  }
}

TEST(Sound, AfibBeatToBeatIntervalsAreTheSimulatedVentriclesIntervals) {
  const fs::path dir = scratch("afib");
  const std::string scene_file = source("scenes/heart-afib.yaml");
  const std::vector<std::string> d = {"output.duration=6 s", "audio={heart: {s2: {enabled: false}}}"};
  const fs::path wav = dir / "afib.wav";
  const auto r = run(systole() + " render " + scene_file + " -D 'output.duration=6 s' -D 'audio={heart: {s2: {enabled: false}}}'" +
                     " -D output.width=160 -D output.height=120 -o " + (dir / "afib.mp4").string() + " --wav " + wav.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const scene::Scene s = scene::load(scene_file, d);
  std::vector<Turn> shrinks;
  for (const Turn& t : simulated_turns(s, s.audio.heart.regions, s.output.frame_count() - 1))
    if (t.shrink && t.time_s > 0.1 && t.time_s < s.output.duration_s - 0.1) shrinks.push_back(t);
  std::vector<double> heard;
  for (double h : onsets(read_wav(wav)))
    if (h > 0.1 && h < s.output.duration_s - 0.1) heard.push_back(h);
  ASSERT_GE(shrinks.size(), 6u);
  ASSERT_EQ(heard.size(), shrinks.size());
  // Each beat's onset: its turn, or on a plateau whichever of the tied turns the sound took.
  std::vector<double> simulated;
  for (std::size_t i = 0; i < shrinks.size(); ++i) {
    double onset = shrinks[i].time_s;
    for (double t : shrinks[i].ties_s) {
      if (std::abs(t - heard[i]) < std::abs(onset - heard[i])) onset = t;
    }
    simulated.push_back(onset);
  }
  double shortest = 1e9, longest = 0, worst = 0;
  for (std::size_t i = 1; i < heard.size(); ++i) {
    const double sim = simulated[i] - simulated[i - 1], snd = heard[i] - heard[i - 1];
    EXPECT_NEAR(snd, sim, 0.010) << "beat " << i;
    worst = std::max(worst, std::abs(snd - sim));
    shortest = std::min(shortest, sim);
    longest = std::max(longest, sim);
  }
  std::cout << "[ measured ] " << heard.size() - 1 << " intervals " << shortest << " .. " << longest
            << " s; worst difference " << 1e3 * worst << " ms\n";
  EXPECT_GT(longest - shortest, 0.08) << "fibrillation's beats differ in length, and so must the sound's";
}

TEST(Sound, Mp4CarriesAacAndCaptionCuesAndChaptersAndLastsAsLongAsThePictures) {
  if (!have("ffprobe")) GTEST_SKIP() << "ffprobe is not installed";
  const fs::path dir = scratch("mp4_tracks");
  write_file(dir / "h.yaml", small_heart_scene("duration: 1.4 s", kTracks));
  const fs::path video = dir / "h.mp4";
  const auto r = run(systole() + " render " + (dir / "h.yaml").string() + " -o " + video.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto streams = run("ffprobe -v error -show_entries stream=codec_type,codec_name,duration -of csv=p=0 " + video.string());
  EXPECT_NE(streams.output.find("h264,video"), std::string::npos) << streams.output;
  EXPECT_NE(streams.output.find("aac,audio"), std::string::npos) << streams.output;
  EXPECT_NE(streams.output.find("mov_text,subtitle"), std::string::npos) << streams.output;
  // Durations: 0.5 s of card + 1.4 s of clip; the sound within one AAC frame of the video.
  const auto dur = run("ffprobe -v error -select_streams v:0 -show_entries stream=duration -of csv=p=0 " + video.string());
  const auto adur = run("ffprobe -v error -select_streams a:0 -show_entries stream=duration -of csv=p=0 " + video.string());
  EXPECT_NEAR(std::stod(dur.output), 1.9, 1e-3) << dur.output;
  EXPECT_NEAR(std::stod(adur.output), std::stod(dur.output), 1024.0 / 48000) << adur.output;
  EXPECT_NEAR(decode_audio(video).size() / 48000.0, 1.9, 1024.0 / 48000);
  // The subtitle track's cues are the captions, shifted by the card.
  const auto cues = run("ffmpeg -v error -i " + video.string() + " -map 0:s:0 -f webvtt -");
  EXPECT_NE(cues.output.find("00:00.600 --> 00:01.100\nFirst words"), std::string::npos) << cues.output;
  EXPECT_NE(cues.output.find("00:01.300 --> 00:01.700\nThen more"), std::string::npos) << cues.output;
  // And so are the .vtt file's.
  const std::string vtt = read_file(dir / "h.vtt");
  EXPECT_NE(vtt.find("00:00:00.600 --> 00:00:01.100\nFirst words\n"), std::string::npos) << vtt;
  EXPECT_NE(vtt.find("00:00:01.300 --> 00:00:01.700\nThen more\n"), std::string::npos) << vtt;
  // Chapters: the card's title line, then the scene's chapter.
  const auto ch = run("ffprobe -v error -show_chapters -of csv=p=0 " + video.string());
  EXPECT_NE(ch.output.find("Title"), std::string::npos) << ch.output;
  EXPECT_NE(ch.output.find("Beat"), std::string::npos) << ch.output;
}

TEST(Sound, WebmCarriesOpusAndWebVttAndMkvFlacAndSubRip) {
  if (!have("ffprobe")) GTEST_SKIP() << "ffprobe is not installed";
  const fs::path dir = scratch("webm_mkv_tracks");
  write_file(dir / "h.yaml", small_heart_scene("duration: 0.6 s", kTracks));
  for (const auto& [ext, audio, text] : {std::tuple{"webm", "opus", "webvtt"}, std::tuple{"mkv", "flac", "subrip"}}) {
    const fs::path video = dir / (std::string("h.") + ext);
    const auto r = run(systole() + " render " + (dir / "h.yaml").string() + " -o " + video.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto streams = run("ffprobe -v error -show_entries stream=codec_type,codec_name -of csv=p=0 " + video.string());
    EXPECT_NE(streams.output.find(std::string(audio) + ",audio"), std::string::npos) << ext << ": " << streams.output;
    EXPECT_NE(streams.output.find(std::string(text) + ",subtitle"), std::string::npos) << ext << ": " << streams.output;
    EXPECT_NEAR(decode_audio(video).size() / 48000.0, 1.1, 1024.0 / 48000) << ext;
  }
}

TEST(Sound, WavIsTheSoundtrackAloneAndGifHasNone) {
  const fs::path dir = scratch("wav_gif");
  write_file(dir / "h.yaml", small_heart_scene("duration: 0.6 s", kTracks));
  const auto r = run(systole() + " render " + (dir / "h.yaml").string() + " -o " + (dir / "h.gif").string() + " --wav " +
                     (dir / "h.wav").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string wav = read_file(dir / "h.wav");
  ASSERT_GT(wav.size(), 44u);
  EXPECT_EQ(wav.substr(0, 4), "RIFF");
  EXPECT_EQ(wav.substr(8, 4), "WAVE");
  EXPECT_EQ((wav.size() - 44) / 2, 48000u * 11 / 10) << "card 0.5 s + clip 0.6 s at 48 kHz";
  EXPECT_GT(onsets(read_wav(dir / "h.wav")).size(), 0u);
  const auto v = run(systole() + " validate " + (dir / "h.yaml").string() + " -D output.format=gif");
  EXPECT_NE(v.output.find("a GIF has no sound"), std::string::npos) << v.output;
  // A scene without audio: --wav is refused, nothing written.
  write_file(dir / "quiet.yaml", small_heart_scene("duration: 0.2 s", ""));
  const auto q = run(systole() + " render " + (dir / "quiet.yaml").string() + " -o " + (dir / "q.mp4").string() + " --wav " +
                     (dir / "q.wav").string());
  EXPECT_EQ(q.exit_code, 64) << q.output;
  EXPECT_NE(q.output.find("has no audio: section"), std::string::npos) << q.output;
  EXPECT_FALSE(fs::exists(dir / "q.wav"));
}

TEST(Sound, AClipWithAudioStepsTheSimulationOncePerStepOfTheClip) {
  // The soundtrack listens to the clip's own run: the pictures replay the frames it kept,
  // so the steps are the clip's and the half second past its end that confirms the last
  // sounds - not the clip twice, as when the sound ran a simulation of its own.
  const fs::path dir = scratch("one_run");
  write_file(dir / "h.yaml", small_heart_scene("duration: 1 s", kTracks));
  const scene::Scene s = scene::load(dir / "h.yaml");
  const world::World w = world::build_world(s);
  const int frames = s.output.frame_count();
  const int extra = static_cast<int>(std::ceil(0.5 / w.frame_s));  // clip/soundtrack.h
  const long long steps_per_frame = w.steps_per_frame * static_cast<long long>(w.organs.size());
  clip::RenderRequest with_sound;
  with_sound.video = dir / "h.mp4";
  const clip::StageTimes heard = clip::render_clip(s, with_sound);
  EXPECT_EQ(heard.steps, (frames + extra - 1) * steps_per_frame);
  EXPECT_LT(heard.steps, 2 * (frames - 1) * steps_per_frame);
  clip::RenderRequest silent;
  silent.png_dir = dir / "png";  // No video: no soundtrack.
  const clip::StageTimes quiet = clip::render_clip(s, silent);
  EXPECT_EQ(quiet.steps, (frames - 1) * steps_per_frame);
  // Replayed or simulated alongside the pictures, the frames are the same bits.
  clip::RenderRequest both;
  both.video = dir / "h2.mp4";
  both.png_dir = dir / "png2";
  clip::render_clip(s, both);
  for (int f : {0, frames / 2, frames - 1}) {
    const std::string name = encode::frame_file_name(f, frames);
    EXPECT_EQ(read_file(dir / "png2" / name), read_file(dir / "png" / name)) << name;
  }
}

}  // namespace
}  // namespace systole::test
