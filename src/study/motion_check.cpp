#include "study/motion_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "common/error.h"
#include "study/driven_regions.h"
#include "study/lining_view.h"
#include "study/lining_watch.h"
#include "world/frame_source.h"
#include "world/world.h"

namespace systole::study {
namespace {

/// Samples per beat when beats are compared (the frames fall at other phases each beat).
constexpr int kPhases = 48;

/// The signal at time t_s, linear between frames sampled every frame_s from t0_s.
double at_time(const std::vector<double>& signal, double t0_s, double frame_s, double t_s) {
  const double u = (t_s - t0_s) / frame_s;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, static_cast<int>(signal.size()) - 2);
  const double w = std::clamp(u - i, 0.0, 1.0);
  return (1 - w) * signal[i] + w * signal[i + 1];
}

RegionBeats compare_beats(const DrivenRegion& region, const std::vector<double>& signal, double t0_s, double frame_s,
                          int settle_beats) {
  RegionBeats out{region.name, 1 / region.rate_hz};
  const double t_end = t0_s + frame_s * static_cast<double>(signal.size() - 1);
  const int beats = static_cast<int>(std::floor((t_end - t0_s) / out.period_s + 1e-9));
  std::vector<double> before;
  for (int k = settle_beats; k < beats; ++k) {
    std::vector<double> beat(kPhases);
    for (int m = 0; m < kPhases; ++m) beat[m] = at_time(signal, t0_s, frame_s, t0_s + (k + m / double(kPhases)) * out.period_s);
    const auto [lo, hi] = std::minmax_element(beat.begin(), beat.end());
    if (!before.empty()) {
      const auto [blo, bhi] = std::minmax_element(before.begin(), before.end());
      double sum = 0;
      for (int m = 0; m < kPhases; ++m) sum += (beat[m] - before[m]) * (beat[m] - before[m]);
      const double ptp = *bhi - *blo;
      const double change = ptp > 0 ? 100 * std::sqrt(sum / kPhases) / ptp : HUGE_VAL;
      if (change >= out.worst_change_pct) {
        out.worst_change_pct = change;
        out.worst_beat = k;
      }
    }
    out.peak_to_peak_m = *hi - *lo;
    before = std::move(beat);
    ++out.beats;
  }
  return out;
}

}  // namespace

bool MotionReport::periodic() const {
  return std::all_of(regions.begin(), regions.end(),
                     [](const RegionBeats& r) { return r.worst_change_pct <= kBeatToBeatTolerancePct; });
}

bool MotionReport::parts_kept() const {
  return std::all_of(organs.begin(), organs.end(),
                     [](const OrganParts& o) { return o.worst.depth_m <= kCrossingTolerance_m; });
}

bool MotionReport::linings_inside() const {
  return std::all_of(linings.begin(), linings.end(), [](const OrganLinings& l) { return l.worst_outside == 0; }) &&
         view.worst_pixels == 0;
}

namespace {

/// Refuses a check with nothing to check: too short for two beats after settling, and no
/// parts or linings.
void check_something_to_check(const MotionReport& report, const std::vector<DrivenRegion>& regions,
                              const std::vector<PartCrossingWatch>& watches, const std::vector<LiningWatch>& linings,
                              const MotionOptions& options) {
  const bool any_parts =
      std::any_of(watches.begin(), watches.end(), [](const PartCrossingWatch& w) { return w.parts().size() >= 2; }) ||
      std::any_of(linings.begin(), linings.end(), [](const LiningWatch& l) { return !l.empty(); });
  double shortest_two_beats = HUGE_VAL;
  for (const auto& r : regions) shortest_two_beats = std::min(shortest_two_beats, (options.settle_beats + 2) / r.rate_hz);
  if (report.duration_s < shortest_two_beats && !any_parts) {
    throw Error(ExitCode::kUsage, "motion: nothing to check in " + report.scene +
                                      ": no periodically driven region has " + std::to_string(options.settle_beats + 2) +
                                      " beats in " + std::to_string(report.duration_s) + " s (the first " +
                                      std::to_string(options.settle_beats) +
                                      " left out) and no organ has parts; give a longer --duration");
  }
}

/// What the linings' watches and the outside view saw, into the report.
void report_linings(const scene::Scene& scene, const std::vector<LiningWatch>& linings, const LiningView* view,
                    MotionReport& report) {
  for (std::size_t o = 0; o < linings.size(); ++o) {
    const LiningWatch& l = linings[o];
    if (l.empty()) continue;
    report.linings.push_back({scene.organs[o].name, l.lining_vertices(), l.frames(), l.frames_outside(), l.worst_outside(),
                              l.worst_frame(), l.worst_cavity()});
  }
  if (view && !view->empty()) {
    report.view = {true, view->width(), view->height(), view->frames(), view->frames_with_pixels(), view->worst_pixels(),
                   view->worst_frame()};
  }
}

/// The linings' lines of the report: each organ's against its walls, the outside view's.
std::string linings_text(const MotionReport& r) {
  std::ostringstream out;
  char line[512];
  for (const auto& l : r.linings) {
    std::snprintf(line, sizeof line, "  linings of %s (%d vertices) against its walls' outside, %d frames: ", l.organ.c_str(),
                  l.lining_vertices, l.frames);
    out << line;
    if (l.worst_outside == 0) {
      out << "none outside\n";
    } else {
      std::snprintf(line, sizeof line, "up to %d outside (frame %d, %s), in %d frames  LINING CROSSES THE WALL\n",
                    l.worst_outside, l.worst_frame, l.worst_cavity.c_str(), l.frames_outside);
      out << line;
    }
  }
  if (r.view.drawn) {
    std::snprintf(line, sizeof line, "  outside view (uncut, opaque, coloured by region, %dx%d), %d frames: ", r.view.width,
                  r.view.height, r.view.frames);
    out << line;
    if (r.view.worst_pixels == 0) {
      out << "no lining pixel\n";
    } else {
      std::snprintf(line, sizeof line, "up to %d lining pixels (frame %d), in %d frames  LINING SHOWS\n", r.view.worst_pixels,
                    r.view.worst_frame, r.view.frames_with_pixels);
      out << line;
    }
  }
  return out.str();
}

}  // namespace

MotionReport check_motion(const scene::Scene& scene, const MotionOptions& options) {
  world::FrameSource source(scene);
  const world::World& world = source.world();
  MotionReport report;
  report.scene = scene.path;
  report.duration_s = options.duration_s > 0 ? options.duration_s : scene.output.duration_s;
  report.frames = static_cast<int>(std::lround(report.duration_s / world.frame_s));
  report.band_m = options.band_m;
  report.settle_beats = options.settle_beats;

  const std::vector<DrivenRegion> regions = driven_regions(scene, world);
  std::vector<PartCrossingWatch> watches;
  std::vector<LiningWatch> linings;
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& body = world.organs[o];
    report.bodies.push_back(scene.organs[o].name + ": " +
                            (body.lattice > 0 ? "lattice " + std::to_string(body.lattice) : std::string("full model")) +
                            " (" + body.body_reason + ")");
    const bool anatomy = !body.geometry.mesh.anatomy.empty();
    if (anatomy) report.anatomies.push_back(scene.organs[o].name);
    // An empty mesh stands in for an anatomy's: nothing to watch (MotionReport::anatomies).
    watches.emplace_back(anatomy ? mesh::OrganMesh{} : body.geometry.mesh, options.band_m);
    linings.emplace_back(body.geometry.mesh);
  }
  std::unique_ptr<LiningView> view;
  if (options.outside_view) view = std::make_unique<LiningView>(scene, world);
  check_something_to_check(report, regions, watches, linings, options);

  // The check listens to every frame of the run: the parts' crossings, the regions' beats.
  std::vector<std::vector<double>> signals(regions.size());
  std::vector<Eigen::Matrix3Xd> positions(world.organs.size());
  Eigen::Matrix3Xd stacked;
  double t0_s = 0;  // Organ time of clip frame 0 (after a loop's settling frames).
  source.on_frame([&](int f) {
    if (f == 0 && !world.organs.empty()) t0_s = world.organs[0].state.time_s;
    for (std::size_t o = 0; o < world.organs.size(); ++o) {
      source.positions(static_cast<int>(o), positions[o]);
      if (f > 0) watches[o].check(positions[o], f);
      if (f < report.frames) linings[o].check(positions[o], f);  // The clip's frames.
    }
    if (view && f < report.frames) view->lining_pixels(positions, f);
    source.stacked_positions(stacked);
    for (std::size_t r = 0; r < regions.size(); ++r) signals[r].push_back(radial_excursion_m(regions[r], stacked));
  });
  source.advance_to(report.frames);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    RegionBeats beats = compare_beats(regions[r], signals[r], t0_s, world.frame_s, options.settle_beats);
    if (beats.beats >= 2) report.regions.push_back(std::move(beats));
  }
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    if (watches[o].parts().size() < 2) continue;
    report.organs.push_back({scene.organs[o].name, watches[o].parts(), watches[o].pairs_compared(), watches[o].worst()});
  }
  report_linings(scene, linings, view.get(), report);
  return report;
}

std::string motion_text(const MotionReport& r) {
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line, "%s: %.3g s, %d frames\n", r.scene.c_str(), r.duration_s, r.frames);
  out << line;
  for (const auto& b : r.bodies) out << "  body " << b << "\n";
  if (!r.regions.empty()) {
    out << "  beats (radial excursion of each driven region; each beat against the one before, the first "
        << (r.settle_beats == 1 ? std::string("") : std::to_string(r.settle_beats) + " ") << "left out):\n";
  }
  for (const auto& g : r.regions) {
    std::snprintf(line, sizeof line, "    %-32s %2d beats of %.3f s, %.3f mm peak to peak, worst change %.2f %% (beat %d)%s\n",
                  g.name.c_str(), g.beats, g.period_s, g.peak_to_peak_m * 1e3, g.worst_change_pct, g.worst_beat,
                  g.worst_change_pct <= kBeatToBeatTolerancePct ? "" : "  NOT PERIODIC");
    out << line;
  }
  for (const auto& o : r.organs) {
    std::snprintf(line, sizeof line, "  parts of %s (%zu; %zu vertex-part pairs came within the band):",
                  o.organ.c_str(), o.parts.size(), o.pairs_compared);
    out << line;
    for (std::size_t i = 0; i < o.parts.size(); ++i) out << (i == 0 ? " " : ", ") << o.parts[i];
    out << "\n";
    if (o.worst.vertex < 0) {
      out << "    no vertex passed through another part\n";
    } else {
      std::snprintf(line, sizeof line, "    deepest crossing %s%.3f mm: a vertex of %s through %s at frame %d%s\n",
                    o.worst.depth_m >= 0.999 * r.band_m ? "at least " : "", o.worst.depth_m * 1e3, o.worst.from.c_str(), o.worst.into.c_str(), o.worst.frame,
                    o.worst.depth_m <= kCrossingTolerance_m ? " (within the tolerance)" : "  PARTS PASS THROUGH");
      out << line;
    }
  }
  for (const auto& a : r.anatomies) {
    out << "  parts of " << a << ": a generated anatomy, its parts labels on one welded wall (its linings are checked instead)\n";
  }
  out << linings_text(r);
  std::snprintf(line, sizeof line, "periodic (every beat within %.0f %% of the one before): %s\n", kBeatToBeatTolerancePct,
                r.regions.empty() ? "no periodic region" : r.periodic() ? "yes" : "no");
  out << line;
  std::snprintf(line, sizeof line, "parts kept apart (no crossing beyond %.1f mm): %s\n", kCrossingTolerance_m * 1e3,
                r.organs.empty() ? "no multi-part organ" : r.parts_kept() ? "yes" : "no");
  out << line;
  if (!r.linings.empty()) out << "linings inside their walls: " << (r.linings_inside() ? "yes" : "no") << "\n";
  return out.str();
}

}  // namespace systole::study
