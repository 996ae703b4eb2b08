// The output tables: the video file, the loop, title cards and captions.

#include "scene/schema/parts.h"

#include <cctype>
#include <filesystem>

namespace systole::scene::schema {
namespace {

std::string format_name(Format f) {
  switch (f) {
    case Format::kMp4:
      return "mp4";
    case Format::kMkv:
      return "mkv";
    case Format::kWebm:
      return "webm";
    case Format::kGif:
      return "gif";
    default:
      return "auto";
  }
}

/// The format a file's extension names (any case); kAuto for none.
Format format_of_file(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (Format f : {Format::kMp4, Format::kMkv, Format::kWebm, Format::kGif})
    if (ext == "." + format_name(f)) return f;
  return Format::kAuto;
}

/// A periodic drive of the scene, with where it was written, for resolve_loop.
struct Rhythm {
  const Drive* drive;
  std::string path;
  Origin origin;
};

}  // namespace

ValueSpec<Card> card_spec() {
  return map<Card>(
      {
          field("text", screen_text(500, false), &Card::text,
                "The card's words; a line break (\\n, or a YAML block) starts a smaller line under the title.")
              .required(),
          field("duration", quantity(Dimension::kTime, open_closed(0, 60)), &Card::duration_s,
                "How long the card shows (video time)."),
          field("fade", quantity(Dimension::kTime, closed(0, 10)), &Card::fade_s,
                "Fade in at the start and out at the end."),
          field("size", number(open_closed(0, 0.5)), &Card::size, "Title height as a fraction of the frame height."),
          field("color", color(), &Card::color, "Text colour (sRGB); the card is the background colour."),
      },
      [](const Node& node, Card& c, const std::string& path, const Context&) {
        if (2 * c.fade_s > c.duration_s)
          fail(origin_of(node, "fade"), join(path, "fade"),
               "twice the fade (" + format_number(c.fade_s) + " s) must fit in the duration (" +
                   format_number(c.duration_s) + " s)");
        c.origin = node.origin;
      });
}

ValueSpec<Caption> caption_spec() {
  return map<Caption>(
      {
          field("text", screen_text(500, false), &Caption::text, "The caption's words, one line.").required(),
          field("from", quantity(Dimension::kTime, closed(0, 36000)), &Caption::from_s,
                "Start, in video time from the clip's first frame (after the cards).")
              .required(),
          field("to", quantity(Dimension::kTime, open_closed(0, 36000)), &Caption::to_s,
                "End, in video time (after from).")
              .required(),
          field("fade", quantity(Dimension::kTime, closed(0, 10)), &Caption::fade_s,
                "Fade in after from and out before to."),
          field("size", number(open_closed(0, 0.5)), &Caption::size, "Text height as a fraction of the frame height."),
          field("color", color(), &Caption::color, "Text colour (sRGB), over a dark band."),
      },
      [](const Node& node, Caption& c, const std::string& path, const Context&) {
        if (c.to_s <= c.from_s)
          fail(origin_of(node, "to"), join(path, "to"),
               format_number(c.to_s) + " s must be after from (" + format_number(c.from_s) + " s)");
        if (2 * c.fade_s > c.to_s - c.from_s)
          fail(origin_of(node, "fade"), join(path, "fade"),
               "twice the fade (" + format_number(c.fade_s) + " s) must fit between from and to (" +
                   format_number(c.to_s - c.from_s) + " s)");
        c.origin = node.origin;
      });
}

ValueSpec<Chapter> chapter_spec() {
  return map<Chapter>(
      {
          field("title", screen_text(200, true), &Chapter::title, "The chapter's name in players' chapter menus.")
              .required(),
          field("at", quantity(Dimension::kTime, closed(0, 36000)), &Chapter::at_s,
                "Start, in video time from the clip's first frame (after the cards), as captions.")
              .required(),
      },
      [](const Node& node, Chapter& c, const std::string&, const Context&) { c.origin = node.origin; });
}

ValueSpec<Output> output_spec() {
  auto even_size = whole<int>(16, 7680).also(
      [](const int& v) {
        return v % 2 == 0 ? std::string()
                          : std::to_string(v) + " is odd; H.264 with yuv420p needs even sizes; use " +
                                std::to_string(v - 1) + " or " + std::to_string(v + 1);
      },
      "16..7680, even");
  return map<Output>(
      {
          field("file", path_text(), &Output::file, "Video path (relative to the working directory).")
              .shown_default("out/<scene name>.<format>"),
          field("width", even_size, &Output::width, "Frame width in pixels."),
          field("height", even_size, &Output::height, "Frame height in pixels."),
          field("fps", number(open_closed(0, 240)), &Output::fps, "Frames per second of video."),
          field("format",
                choice<Format>({{"auto", Format::kAuto},
                                {"mp4", Format::kMp4},
                                {"mkv", Format::kMkv},
                                {"webm", Format::kWebm},
                                {"gif", Format::kGif}}),
                &Output::format,
                "Container and codec: mp4 (H.264), mkv (FFV1, lossless RGB), webm (VP9), gif (one palette, for "
                "slides); auto takes the video file's extension (.mp4, .mkv, .webm, .gif), else mp4."),
          field("duration", quantity(Dimension::kTime, open_closed(0, 3600)), &Output::duration_s,
                "Organ time the clip shows (the video lasts duration x slow_motion); with loop, rounded to whole "
                "cycles."),
          field("slow_motion", number(closed(0.1, 100)), &Output::slow_motion,
                "Video seconds per second of organ time: 4 plays a beat 4x slower (the body is still simulated at its "
                "true rate); below 1 speeds up."),
          field("loop", boolean(), &Output::loop,
                "Make a seamless loop: duration snaps to whole cycles of the slowest drive (and of every other), the "
                "clip starts after settle_cycles, and its last frame flows into its first."),
          field("settle_cycles", whole<int>(0, 100), &Output::settle_cycles,
                "loop: cycles of the slowest drive simulated (not shown) before the clip starts, at least; rounded up "
                "to whole loops."),
          field("quality",
                choice<Quality>(
                    {{"draft", Quality::kDraft}, {"standard", Quality::kStandard}, {"archival", Quality::kArchival}}),
                &Output::quality,
                "Encoder settings by purpose: draft (x264 ultrafast, CRF 23), standard (veryfast, CRF 20), archival "
                "(slow, CRF 16). crf and preset override them."),
          field("crf", whole<int>(0, 51), &Output::crf,
                "x264 constant rate factor: 0 lossless (High 4:4:4 Predictive profile, which some browsers do not "
                "play), 51 worst.")
              .shown_default("by quality"),
          field("preset",
                choice<std::string>({{"ultrafast", "ultrafast"},
                                     {"superfast", "superfast"},
                                     {"veryfast", "veryfast"},
                                     {"faster", "faster"},
                                     {"fast", "fast"},
                                     {"medium", "medium"},
                                     {"slow", "slow"},
                                     {"slower", "slower"},
                                     {"veryslow", "veryslow"},
                                     {"placebo", "placebo"}}),
                &Output::preset, "x264 speed/size preset.")
              .shown_default("by quality"),
          // 0, 2 and 4 are the sample counts this key took before FXAA existed.
          field("antialias",
                choice<Antialias>({{"off", Antialias::kOff},
                                   {"fxaa", Antialias::kFxaa},
                                   {"msaa2", Antialias::kMsaa2},
                                   {"msaa4", Antialias::kMsaa4},
                                   {"0", Antialias::kOff},
                                   {"2", Antialias::kMsaa2},
                                   {"4", Antialias::kMsaa4}}),
                &Output::antialias,
                "Edge smoothing: fxaa (a post pass, cheap), msaa2 or msaa4 (2 or 4 samples per pixel, slower), off; 0, "
                "2, 4 mean off, msaa2, msaa4."),
          field("background", color(), &Output::background, "Background colour (sRGB)."),
          field("burn_captions", boolean(), &Output::burn_captions,
                "Draw the captions into the frames. Either way they are also a subtitle track (MP4, MKV, WebM) and a "
                ".vtt file beside the video."),
      },
      [](const Node& node, Output& o, const std::string& path, const Context&) {
        // The quality names a preset and CRF (measured: docs/performance.md); keys written out win.
        const auto [crf, preset] = o.quality == Quality::kDraft      ? std::pair{23, "ultrafast"}
                                   : o.quality == Quality::kArchival ? std::pair{16, "slow"}
                                                                     : std::pair{20, "veryfast"};
        if (!node.find("crf")) o.crf = crf;
        if (!node.find("preset")) o.preset = preset;
        const Format named = format_of_file(o.file);
        if (o.format != Format::kAuto && named != Format::kAuto && named != o.format)
          fail(origin_of(node, "format"), join(path, "format"),
               "'" + format_name(o.format) + "' contradicts the file '" + o.file + "' (its extension names " +
                   format_name(named) + "); drop one");
        if (o.format == Format::kAuto) o.format = named == Format::kAuto ? Format::kMp4 : named;
        if (o.format == Format::kGif && o.fps > 50)
          fail(origin_of(node, "fps"), join(path, "fps"),
               format_number(o.fps) +
                   " is outside (0, 50] for a GIF: its delays are whole "
                   "centiseconds and browsers slow faster GIFs to 10 fps; use 25 or 50");
      });
}

namespace {

// Every rhythm the loop must repeat, with where it is written; a prescribed motion or a
// one-off poke cannot repeat, so either fails here.
std::vector<Rhythm> loop_rhythms(const Scene& s) {
  std::vector<Rhythm> rhythms;
  for (std::size_t i = 0; i < s.organs.size(); ++i) {
    const Organ& organ = s.organs[i];
    const std::string at = "organs[" + std::to_string(i) + "]";
    if (organ.body.volume_drive.waveform != Waveform::kNone)
      rhythms.push_back({&organ.body.volume_drive, at + ".body.volume_drive", organ.origin});
    for (std::size_t r = 0; r < organ.regions.size(); ++r) {
      const Region& region = organ.regions[r];
      const std::string region_at = at + ".regions[" + std::to_string(r) + "]";
      if (!region.motion.empty())
        fail(region.origin, region_at + ".motion",
             "a prescribed motion is held after its last key, so output.loop cannot repeat it; drop the loop or the "
             "motion");
      if (region.drive.waveform != Waveform::kNone && !region.pinned)
        rhythms.push_back({&region.drive, region_at + ".drive", region.origin});
    }
  }
  for (std::size_t i = 0; i < s.interactions.size(); ++i) {
    const Interaction& in = s.interactions[i];
    const std::string at = "interactions[" + std::to_string(i) + "]";
    if (in.kind == InteractionKind::kPoke && in.drive.waveform != Waveform::kNone) {
      rhythms.push_back({&in.drive, at + ".poke.drive", in.origin});
    } else {
      fail(in.origin, at,
           "happens once, so output.loop cannot repeat it seamlessly; drop the loop or give the poke a drive");
    }
  }
  return rhythms;
}

}  // namespace

/// output.loop: duration becomes the shortest whole number of cycles of the slowest drive
/// in which every other drive also completes whole cycles (within 0.1% of a cycle), times
/// round(duration / that); start_frame skips settle_cycles of the slowest drive, rounded up to
/// whole loops, so the clip starts at the same phase as t = 0.
void resolve_loop(const Node& node, Scene& s) {
  Output& o = s.output;
  const Node* output_node = node.find("output");
  const Origin& where = output_node ? origin_of(*output_node, "loop") : node.origin;
  const std::vector<Rhythm> rhythms = loop_rhythms(s);
  if (rhythms.empty()) fail(where, "output.loop", "no region is driven, so there is no cycle to loop on");
  const Rhythm* slowest = &rhythms[0];
  for (const Rhythm& r : rhythms) {
    if (r.drive->rate_end_hz > 0)
      fail(r.origin, r.path + ".rate_end",
           "a ramping rate never repeats, so output.loop cannot close; drop rate_end or the loop");
    if (r.drive->irregularity > 0)
      fail(r.origin, r.path + ".irregularity",
           "an irregular rhythm never repeats, so output.loop cannot close; set it to 0 or drop the loop");
    if (r.drive->rate_hz < slowest->drive->rate_hz) slowest = &r;
  }
  if (!(slowest->drive->rate_hz > 0)) fail(slowest->origin, slowest->path + ".rate", "a loop needs a rate above 0");
  const double period = 1.0 / slowest->drive->rate_hz;
  int cycles = 0;  // Of the slowest drive, in which every drive completes whole cycles.
  for (int n = 1; n <= 64 && cycles == 0; ++n) {
    const bool whole = std::all_of(rhythms.begin(), rhythms.end(), [&](const Rhythm& r) {
      const double c = r.drive->rate_hz * n * period;
      return std::abs(c - std::round(c)) < 1e-3;
    });
    if (whole) cycles = n;
  }
  if (cycles == 0)
    fail(where, "output.loop",
         "the drives have no common cycle within 64 cycles of the slowest (" + slowest->path + " at " +
             format_quantity(slowest->drive->rate_hz, Dimension::kFrequency) +
             "); give them rates in whole-number ratios");
  const double common = cycles * period;
  const int repeats = std::max(1, static_cast<int>(std::lround(o.duration_s / common)));
  o.duration_s = repeats * common;
  if (o.frame_count() < 2)
    fail(where, "output.loop",
         "the loop (" + format_number(o.duration_s) + " s) is shorter than two frames; raise output.fps");
  const int loops_to_settle = static_cast<int>(std::ceil(o.settle_cycles * period / o.duration_s - 1e-9));
  o.start_frame = loops_to_settle * o.frame_count();
}

}  // namespace systole::scene::schema
