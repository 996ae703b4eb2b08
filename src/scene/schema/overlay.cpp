// The teaching tables: split-screen views and overlays (title, labels, legend, traces, ECG sheet).

#include "scene/schema/parts.h"

namespace systole::scene::schema {
namespace {

/// Text shown on screen (a title): any UTF-8 without control characters.
ValueSpec<std::string> display_text() {
  ValueSpec<std::string> spec;
  spec.type = "text";
  spec.range = "1..120 characters";
  spec.read = [](const Node& node, std::string& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kScalar || node.scalar.empty())
      fail(node.origin, path, "expected text such as \"Sinus rhythm\"; got " + node.describe());
    const std::string& s = node.scalar;
    if (s.size() > 120) fail(node.origin, path, "text of " + std::to_string(s.size()) + " bytes is longer than 120");
    if (std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
      fail(node.origin, path, "text must not contain control characters (tabs, line breaks)");
    out = s;
  };
  spec.show = [](const std::string& v) { return v.empty() ? std::string("none") : v; };
  return spec;
}

/// A standard ECG lead's name.
ValueSpec<std::string> ecg_lead() {
  std::vector<std::pair<std::string, std::string>> leads;
  for (const char* name : {"I", "II", "III", "aVR", "aVL", "aVF", "V1", "V2", "V3", "V4", "V5", "V6"}) leads.emplace_back(name, name);
  return choice<std::string>(leads);
}

ValueSpec<Corner> corner() {
  return choice<Corner>({{"top-left", Corner::kTopLeft},
                         {"top-right", Corner::kTopRight},
                         {"bottom-left", Corner::kBottomLeft},
                         {"bottom-right", Corner::kBottomRight}});
}

/// `regions` of labels: "all" or a list of region names.
ValueSpec<std::vector<std::string>> region_names() {
  const ValueSpec<std::string> name = name_text();
  ValueSpec<std::vector<std::string>> spec;
  spec.type = "`all` or list of names";
  spec.range = "`all`, or 1..256 region names";
  spec.read = [name](const Node& node, std::vector<std::string>& out, const std::string& path, const Context& ctx) {
    out.clear();
    if (node.kind == Node::Kind::kScalar && node.scalar == "all") return;
    if (node.kind != Node::Kind::kList)
      fail(node.origin, path,
           "expected all or a list of region names, e.g. [left_ventricle, aorta]; got " + node.describe());
    if (node.items.empty() || node.items.size() > 256)  // Empty stands for `all`, so it is not "no labels".
      fail(node.origin, path,
           "expected 1..256 region names, got " + std::to_string(node.items.size()) +
               " (to show no labels, leave out overlay.labels)");
    for (std::size_t i = 0; i < node.items.size(); ++i) {
      std::string n;
      name.read(node.items[i], n, path + "[" + std::to_string(i) + "]", ctx);
      out.push_back(n);
    }
  };
  spec.show = [](const std::vector<std::string>& v) { return v.empty() ? std::string("all") : std::string("—"); };
  return spec;
}

/// overlay.ecg_sheet: a corner and a width (its height follows the paper).
auto ecg_sheet_spec() {
  return map<EcgSheetOverlay>(
      {
          field("organ", name_text(), &EcgSheetOverlay::organ, "The organ whose computed ECG is shown: it needs `electrophysiology`.")
              .shown_default("the first organ"),
          field("position", corner(), &EcgSheetOverlay::position, "Corner of the frame; insets in the same corner stack."),
          field("width", whole<int>(268, 1920), &EcgSheetOverlay::width_px,
                "Sheet width in pixels of a 720-line frame; its height follows the paper's 268:135."),
      },
      [](const Node& node, EcgSheetOverlay& e, const std::string&, const Context&) {
        e.enabled = true;
        e.origin = node.origin;
      });
}

}  // namespace

ValueSpec<View> view_spec() {
  return map<View>(
      {
          field<View, Camera>(
              "camera", camera_spec(),
              [](View& v) -> Camera& {
                v.has_camera = true;
                return v.camera;
              },
              "This view's camera.")
              .shown_default("the scene's camera"),
          field("organs", list(name_text(), 1, 64, "list of names"), &View::organs, "Names of the organs shown.")
              .shown_default("every organ"),
          field("clip", clip_spec(), &View::clip, "Cuts this view's organs that have no clip of their own.")
              .shown_default("none"),
          field("title", screen_text(200, true), &View::title, "Caption of the view, drawn by the overlay."),
      },
      [](const Node& node, View& v, const std::string&, const Context&) { v.origin = node.origin; });
}

ValueSpec<Overlay> overlay_spec() {
  const auto size = whole<int>(6, 96);
  auto labels = map<LabelsOverlay>(
      {
          field("organ", name_text(), &LabelsOverlay::organ, "The organ whose regions are labelled.")
              .shown_default("every organ"),
          field("regions", region_names(), &LabelsOverlay::regions, "The regions labelled."),
          field("view", screen_text(200, true), &LabelsOverlay::view,
                "Title of the view labelled; in a cut view each region is anchored on what the cut keeps of it "
                "(a cavity's lining, a valve).")
              .shown_default("each organ in the first view that shows it"),
          field("size", size, &LabelsOverlay::size_px,
                "Text height in pixels of a 720-line frame (scaled with output.height)."),
      },
      [](const Node& node, LabelsOverlay& l, const std::string&, const Context&) {
        l.enabled = true;
        l.origin = node.origin;
      });
  auto legend = map<LegendOverlay>(
      {
          field("organ", name_text(), &LegendOverlay::organ, "The organ whose region colours are listed.")
              .shown_default("the first organ"),
          field("position", corner(), &LegendOverlay::position, "Corner of the frame."),
          field("size", size, &LegendOverlay::size_px, "Text height in pixels of a 720-line frame."),
      },
      [](const Node& node, LegendOverlay& l, const std::string&, const Context&) {
        l.enabled = true;
        l.origin = node.origin;
      });
  // window is a time or the word "clip" (0 inside).
  const Range window_range = open_closed(0, 600);
  Field<TraceOverlay> window{
      KeySpec{"window",
              "time or `clip`",
              "3 s",
              window_range.text("s") + ", or `clip`",
              "Width of the sweep (the cursor runs across it, then starts over); `clip`: the whole clip at once.",
              {}},
      false, [window_range](const Node& node, TraceOverlay& t, const std::string& path, const Context&) {
        if (node.kind == Node::Kind::kScalar && node.scalar == "clip") {
          t.window_s = 0;
          return;
        }
        const double v = parse_quantity(node, Dimension::kTime, path);
        check_range(node, v, Dimension::kTime, window_range, path);
        t.window_s = v;
      }};
  auto trace = map<TraceOverlay>(
      {
          field("signal",
                choice<TraceSignal>({{"volume", TraceSignal::kVolume},
                                     {"activation", TraceSignal::kActivation},
                                     {"ecg", TraceSignal::kEcg}}),
                &TraceOverlay::signal,
                "`volume`: the organ's enclosed volume as simulated; `activation`: a region's drive phi(t); `ecg`: "
                "the organ's computed ECG lead when it has `electrophysiology`, else a synthetic P-QRS-T at each beat "
                "of a region's drive.")
              .required(),
          field("organ", name_text(), &TraceOverlay::organ, "The organ traced.").shown_default("the first organ"),
          field("region", name_text(), &TraceOverlay::region,
                "`activation`, `ecg`: the driven region whose beats are shown (`ecg`: a QRS-T at each beat: the "
                "ventricles)."),
          field("atria", name_text(), &TraceOverlay::atria,
                "`ecg`: the atrial region whose beats give the P waves; faster than 4 Hz (flutter, fibrillation): no P "
                "waves but f-waves following its drive. Default: a P wave 160 ms before each R."),
          field("lead", ecg_lead(), &TraceOverlay::lead,
                "`ecg` of an organ with `electrophysiology`: the computed lead shown.")
              .shown_default("II"),
          field("chamber", name_text(), &TraceOverlay::chamber,
                "`volume`: a chamber of a generated anatomy (`anatomical_heart`: left_ventricle, right_ventricle, "
                "left_atrium, right_atrium): the blood it holds, from its lining with the valve annuli capped, instead "
                "of the volume the organ's whole surface encloses.")
              .shown_default("the whole organ"),
          field("position", corner(), &TraceOverlay::position, "Corner of the frame; insets in the same corner stack."),
          field("width", whole<int>(60, 1920), &TraceOverlay::width_px, "Inset width in pixels of a 720-line frame."),
          field("height", whole<int>(30, 1080), &TraceOverlay::height_px,
                "Inset height in pixels of a 720-line frame."),
          window,
      },
      [](const Node& node, TraceOverlay& t, const std::string& path, const Context&) {
        t.origin = node.origin;
        if (t.signal != TraceSignal::kEcg && node.find("lead"))
          fail(origin_of(node, "lead"), join(path, "lead"), "lead applies to signal ecg only");
        if (t.signal != TraceSignal::kVolume && !t.chamber.empty())
          fail(origin_of(node, "chamber"), join(path, "chamber"), "chamber applies to signal volume only");
        if (t.signal != TraceSignal::kEcg && !t.atria.empty())
          fail(origin_of(node, "atria"), join(path, "atria"), "atria applies to signal ecg only");
        if (t.signal == TraceSignal::kVolume && !t.region.empty())
          fail(origin_of(node, "region"), join(path, "region"),
               "signal volume is the whole organ's; region applies to activation and ecg");
      });
  return map<Overlay>({
      field("title", display_text(), &Overlay::title, "A title across the top of the frame."),
      field("title_size", size, &Overlay::title_size_px, "Title text height in pixels of a 720-line frame."),
      field("labels", labels, &Overlay::labels,
            "Region names beside their regions, with leader lines, following them as they move.")
          .shown_default("none"),
      field("legend", legend, &Overlay::legend, "A key of the organ's region colours.").shown_default("none"),
      field("traces", list(trace, 0, 8, "list of traces"), &Overlay::traces,
            "Live plots of a signal over time with a moving cursor."),
      field("ecg_sheet", ecg_sheet_spec(), &Overlay::ecg_sheet,
            "The organ's computed 12-lead ECG on ECG paper (25 mm/s, 10 mm/mV; 3x4 leads and a lead II rhythm "
            "strip), written up to the frame's time, page by page of 10 s.")
          .shown_default("none"),
  });
}

namespace {

const Region* find_region(const Organ& o, const std::string& name) {
  for (const Region& r : o.regions)
    if (r.name == name) return &r;
  return nullptr;
}

/// A trace's region and lead against its organ: a computed ECG needs electrophysiology and
/// no region; everything else a driven region.
void check_trace(const TraceOverlay& t, const Node& item, const Organ& organ, const std::string& path) {
  if (t.signal == TraceSignal::kVolume) return;
  if (t.signal == TraceSignal::kEcg && organ.electrophysiology.enabled) {
    if (!t.region.empty() || !t.atria.empty())
      fail(origin_of(item, t.region.empty() ? "atria" : "region"), path + (t.region.empty() ? ".atria" : ".region"),
           "organ '" + organ.name + "' has electrophysiology: its conduction system makes the ECG; give a `lead`");
    return;
  }
  if (t.region.empty())
    fail(item.origin, path,
         "signal activation and ecg need a region: the driven region whose beats are shown (or, for ecg, an organ "
         "with electrophysiology)");
  if (item.find("lead"))
    fail(origin_of(item, "lead"), path + ".lead",
         "organ '" + organ.name + "' has no electrophysiology: its ECG is synthetic, with no leads");
  const Region* r = find_region(organ, t.region);
  if (!r) fail(origin_of(item, "region"), path + ".region", "organ '" + organ.name + "' has no region named '" + t.region + "'");
  if (r->drive.waveform == Waveform::kNone)
    fail(origin_of(item, "region"), path + ".region", "region '" + t.region + "' has no drive: nothing beats to trace");
  if (t.atria.empty()) return;
  const Region* a = find_region(organ, t.atria);
  if (!a) fail(origin_of(item, "atria"), path + ".atria", "organ '" + organ.name + "' has no region named '" + t.atria + "'");
  if (a->drive.waveform == Waveform::kNone)
    fail(origin_of(item, "atria"), path + ".atria", "region '" + t.atria + "' has no drive: it gives no P waves");
}

}  // namespace

/// Cross-checks of the overlay against the organs: every name it uses exists, and traced
/// regions are driven.
void check_overlay(const Node& root, const Scene& s) {
  const Node* node = root.find("overlay");
  if (!node) return;
  auto find_organ = [&](const std::string& name, const Origin& origin, const std::string& path) -> const Organ* {
    if (name.empty()) return &s.organs.front();
    for (const Organ& o : s.organs)
      if (o.name == name) return &o;
    fail(origin, path, "no organ is named '" + name + "'");
    return nullptr;
  };
  const Overlay& ov = s.overlay;
  if (ov.labels.enabled) {
    const Node* labels = node->find("labels");
    if (!ov.labels.organ.empty()) find_organ(ov.labels.organ, origin_of(*labels, "organ"), "overlay.labels.organ");
    for (std::size_t i = 0; i < ov.labels.regions.size(); ++i) {
      const std::string& name = ov.labels.regions[i];
      const bool found = std::any_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) {
        return (ov.labels.organ.empty() || o.name == ov.labels.organ) && find_region(o, name);
      });
      if (!found)
        fail(labels->find("regions")->items[i].origin, "overlay.labels.regions[" + std::to_string(i) + "]",
             "no region is named '" + name + "'" +
                 (ov.labels.organ.empty() ? "" : " in organ '" + ov.labels.organ + "'"));
    }
    if (!ov.labels.view.empty() &&
        std::none_of(s.views.begin(), s.views.end(), [&](const View& v) { return v.title == ov.labels.view; })) {
      std::string titles;
      for (const View& v : s.views) titles += (titles.empty() ? "'" : ", '") + v.title + "'";
      fail(origin_of(*labels, "view"), "overlay.labels.view",
           "no view is titled '" + ov.labels.view + "' (" + (titles.empty() ? "the scene has no views" : "views: " + titles) + ")");
    }
  }
  if (ov.legend.enabled) find_organ(ov.legend.organ, origin_of(*node->find("legend"), "organ"), "overlay.legend.organ");
  if (ov.ecg_sheet.enabled) {
    const Node* sheet = node->find("ecg_sheet");
    const Organ* o = find_organ(ov.ecg_sheet.organ, origin_of(*sheet, "organ"), "overlay.ecg_sheet.organ");
    if (!o->electrophysiology.enabled)
      fail(sheet->origin, "overlay.ecg_sheet",
           "organ '" + o->name + "' has no electrophysiology: only a conduction system's ECG has twelve leads");
  }
  for (std::size_t i = 0; i < ov.traces.size(); ++i) {
    const std::string path = "overlay.traces[" + std::to_string(i) + "]";
    const Node& item = node->find("traces")->items[i];
    check_trace(ov.traces[i], item, *find_organ(ov.traces[i].organ, origin_of(item, "organ"), path + ".organ"), path);
  }
}

}  // namespace systole::scene::schema
