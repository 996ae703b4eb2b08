#include "study/physiology.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/error.h"
#include "sim/reduced.h"
#include "world/frame_source.h"
#include "world/heart_ecg.h"
#include "world/world.h"

namespace systole::study {
namespace {

constexpr double kMl = 1e-6;  // m^3 per ml

Eigen::Vector3d centroid(const std::vector<int>& ring, const Eigen::Matrix3Xd& x) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int v : ring) c += x.col(v);
  return c / static_cast<double>(ring.size());
}

// Mean signed rotation of a ring about `axis` from `before` to `now`, each vertex about its
// ring's centroid. unit: rad
double ring_rotation(const std::vector<int>& ring, const Eigen::Matrix3Xd& before, const Eigen::Matrix3Xd& now,
                     const Eigen::Vector3d& axis) {
  const Eigen::Vector3d c0 = centroid(ring, before), c1 = centroid(ring, now);
  double sum = 0;
  for (int v : ring) {
    Eigen::Vector3d a = before.col(v) - c0, b = now.col(v) - c1;
    a -= a.dot(axis) * axis;
    b -= b.dot(axis) * axis;
    sum += std::atan2(axis.dot(a.cross(b)), a.dot(b));
  }
  return sum / static_cast<double>(ring.size());
}

double muscle_volume(const std::vector<Eigen::Vector3i>& triangles, const Eigen::Matrix3Xd& x) {
  double six = 0;
  for (const auto& t : triangles) six += x.col(t[0]).dot(x.col(t[1]).cross(x.col(t[2])));
  return six / 6;
}

constexpr const char* kMidSegmentNames[6] = {"anterior", "anteroseptal", "inferoseptal", "inferior", "inferolateral", "anterolateral"};

/// The mean lining-to-epicardium distance of each mid-ventricular segment's pairs (AHA 7-12,
/// in order), the render vertices placed by `at(vertex)`, as echocardiography scores
/// regional motion. unit: m
template <class At>
std::array<double, 6> mid_thickness(const mesh::VentricleLandmarks& lv, const At& at) {
  std::array<double, 6> sum{}, count{};
  for (std::size_t i = 0; i < lv.wall.size(); ++i) {
    const int s = lv.wall_segment[i] - 7;
    if (s < 0 || s >= 6) continue;
    const auto [inner, outer] = lv.wall[i];
    sum[static_cast<std::size_t>(s)] += (at(outer) - at(inner)).norm();
    count[static_cast<std::size_t>(s)] += 1;
  }
  for (std::size_t s = 0; s < 6; ++s) sum[s] = count[s] > 0 ? sum[s] / count[s] : 0.0;
  return sum;
}

// Each mid-ventricular segment's thickening from end-diastole to end-systole.
std::vector<SegmentThickening> segment_thickening(const mesh::VentricleLandmarks& lv, const Eigen::Matrix3Xd& diastole,
                                                  const Eigen::Matrix3Xd& systole) {
  const auto before = mid_thickness(lv, [&](int v) { return Eigen::Vector3d(diastole.col(v)); });
  const auto after = mid_thickness(lv, [&](int v) { return Eigen::Vector3d(systole.col(v)); });
  std::vector<SegmentThickening> out;
  for (std::size_t s = 0; s < 6; ++s) {
    if (before[s] > 0) out.push_back({int(s) + 7, kMidSegmentNames[s], 100 * (after[s] / before[s] - 1)});
  }
  return out;
}

}  // namespace

std::vector<std::string> PhysiologyReport::outside_normal() const {
  std::vector<std::string> out;
  auto check = [&](const char* name, double value, const NormalRange& range) {
    if (!std::isnan(value) && !range.holds(value)) out.push_back(name);  // A figure not measured is not judged.
  };
  check("end-diastolic volume", end_diastolic_ml, kEndDiastolicVolume);
  check("end-systolic volume", end_systolic_ml, kEndSystolicVolume);
  check("ejection fraction", ejection_fraction_pct, kEjectionFraction);
  check("long-axis shortening", long_axis_shortening_pct, kLongAxisShortening);
  check("wall thickening", wall_thickening_pct, kWallThickening);
  check("twist", twist_deg, kTwist);
  check("ejection time", ejection_pct, kEjectionShare);
  check("isovolumic relaxation", isovolumic_relaxation_ms, kIsovolumicRelaxation);
  if (has_ecg) {
    check("PR interval", 1000 * ecg.pr_s, kPrInterval);
    check("QRS duration", 1000 * ecg.qrs_s, kQrsDuration);
    check("QTc", 1000 * ecg.qtc_s, kQtc);
    check("QRS axis", ecg.axis_deg, kQrsAxis);
    check("R/S transition", ecg.transition, kTransition);
    check("electromechanical delay", electromechanical_delay_ms, kElectromechanicalDelay);
  }
  return out;
}

namespace {

/// The first organ with a generated anatomy. Throws Error(kUsage) when none has one.
int anatomical_organ(const scene::Scene& scene, const world::World& world) {
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    if (!world.organs[o].geometry.mesh.anatomy.empty()) return static_cast<int>(o);
  }
  throw Error(ExitCode::kUsage, scene.path + ": --physiology measures a generated anatomical heart "
                                             "(mesh: {procedural: heart}); no organ of this scene has one");
}

/// The left ventricle's periodic drive, which times the beat. Throws Error(kUsage) without one.
const sim::RegionParams& left_ventricle_drive(const scene::Scene& scene, const sim::Model& model) {
  const sim::RegionParams* ventricle = nullptr;
  for (const auto& r : model.regions) {
    if (r.name == "left_ventricle" && r.drive.waveform != sim::Waveform::kNone && r.drive.rate_hz > 0) ventricle = &r;
  }
  if (!ventricle) {
    throw Error(ExitCode::kUsage, scene.path + ": --physiology times the beat by the left ventricle's drive; organ '" +
                                      model.name + "' has no region left_ventricle with a periodic drive");
  }
  return *ventricle;
}

/// What the run shows of the heart around the measured beat: every frame's shape, chamber
/// volumes and valve openings and, with blood, every step's valve states (the ventricles'
/// phases change between solver steps, so the valve events get the step's resolution).
struct HeartRecording {
  std::vector<double> times;  ///< Organ time of each recorded frame. unit: s
  std::vector<Eigen::Matrix3Xd> shapes;
  std::vector<std::vector<double>> volumes, openings;  ///< Per frame, per cavity (ml) / valve.
  std::vector<double> step_times;  ///< With blood. unit: s
  std::vector<std::vector<bool>> step_open;
  /// Every step's mid-ventricular wall thickness per segment (AHA 7-12). unit: s, m
  std::vector<double> wall_times;
  std::vector<std::array<double, 6>> mid_thickness;
};

/// Listens to the source as it runs through frame `last`, recording organ `organ` from frame
/// `first` on (never frame 0: the run is measured after its first step).
HeartRecording record_heart(world::FrameSource& source, int organ, int first, int last) {
  HeartRecording rec;
  const world::OrganBody& body = source.world().organs[static_cast<std::size_t>(organ)];
  if (body.model.circulation.enabled()) {
    source.on_step([&rec, organ](int o, const world::OrganBody& b) {
      if (o != organ) return;
      std::vector<bool> open;
      for (const auto& valve : b.valves.valves) {
        open.push_back(valve.chamber >= 0 && world::valve_open(b.state.chambers[static_cast<std::size_t>(valve.chamber)].phase, valve.inflow));
      }
      rec.step_times.push_back(b.state.time_s);
      rec.step_open.push_back(std::move(open));
    });
  }
  source.on_step([&rec, organ](int o, const world::OrganBody& b) {
    if (o != organ) return;
    rec.wall_times.push_back(b.state.time_s);
    rec.mid_thickness.push_back(mid_thickness(b.geometry.mesh.anatomy.left_ventricle,
                                              [&b](int v) { return sim::embed_vertex(b.embedding, b.state.x, v); }));
  });
  source.on_frame([&rec, &body, first](int f) {
    if (f < 1 || f < first) return;
    rec.times.push_back(body.state.time_s);
    rec.shapes.emplace_back();
    sim::embed(body.embedding, body.state.x, rec.shapes.back());
    std::vector<double> v;
    for (double m3 : body.valves.volume_m3) v.push_back(m3 / kMl);  // Measured by the valves this frame.
    rec.volumes.push_back(std::move(v));
    std::vector<double> o;
    for (const auto& valve : body.valves.valves) o.push_back(valve.opening);
    rec.openings.push_back(std::move(o));
  });
  source.advance_to(last);
  return rec;
}

/// The recorded frames within [start, start + beat).
std::vector<int> beat_frames(const std::vector<double>& times, double start, double beat_s) {
  std::vector<int> beat;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] >= start - 1e-9 && times[i] < start + beat_s - 1e-9) beat.push_back(static_cast<int>(i));
  }
  return beat;
}

/// Valve events: where the opening leaves or returns to 0, between frames (or, with blood,
/// between steps), within the beat; the aortic valve's open share of the beat; and the
/// isovolumic relaxation, from the aortic closure to the mitral opening that follows it (in
/// this beat, or the next one's at the same time in the beat). Returns the aortic closure
/// after activation (ms; NaN when it is not seen).
double measure_valves(const mesh::Anatomy& anatomy, const world::OrganBody& body, const HeartRecording& rec,
                      PhysiologyReport& report) {
  const double start = report.measured_from_s;
  const bool by_step = !rec.step_times.empty();
  const std::vector<double>& event_times = by_step ? rec.step_times : rec.times;
  for (std::size_t v = 0; v < body.valves.valves.size(); ++v) {
    const auto open_at = [&](std::size_t i) { return by_step ? bool(rec.step_open[i][v]) : rec.openings[i][v] > 0; };
    for (std::size_t i = 1; i < event_times.size(); ++i) {
      const bool was_open = open_at(i - 1), is_open = open_at(i);
      if (was_open == is_open) continue;
      const double t = 0.5 * (event_times[i - 1] + event_times[i]);
      if (t < start || t >= start + report.beat_s) continue;
      report.valve_events.push_back({anatomy.valves[v].name, is_open, 1000 * (t - start)});
    }
    if (anatomy.valves[v].name == "aortic_valve") {
      int open = 0, all = 0;
      for (std::size_t i = 0; i < event_times.size(); ++i) {
        if (event_times[i] < start - 1e-9 || event_times[i] >= start + report.beat_s - 1e-9) continue;
        ++all;
        open += open_at(i);
      }
      report.ejection_pct = 100.0 * open / static_cast<double>(all);
    }
  }
  std::sort(report.valve_events.begin(), report.valve_events.end(),
            [](const ValveEvent& a, const ValveEvent& b) { return a.after_activation_ms < b.after_activation_ms; });
  const auto event = [&](const char* valve, bool opens, double from_ms) {
    double first = std::numeric_limits<double>::quiet_NaN();
    for (const ValveEvent& e : report.valve_events) {
      if (e.valve != valve || e.opens != opens) continue;
      const double t = e.after_activation_ms < from_ms ? e.after_activation_ms + 1000 * report.beat_s : e.after_activation_ms;
      if (std::isnan(first) || t < first) first = t;
    }
    return first;
  };
  const double aortic_closes = event("aortic_valve", false, 0);
  if (!std::isnan(aortic_closes)) report.isovolumic_relaxation_ms = event("mitral_valve", true, aortic_closes) - aortic_closes;
  return aortic_closes;
}

/// Each chamber's range over the beat, and the left ventricle's end-diastolic and
/// end-systolic frames (indices into the recording) and volumes.
std::pair<int, int> measure_volumes(const mesh::Anatomy& anatomy, const HeartRecording& rec, const std::vector<int>& beat,
                                    double aortic_closes_ms, PhysiologyReport& report) {
  const auto& volumes = rec.volumes;
  for (std::size_t c = 0; c < anatomy.cavities.size(); ++c) {
    ChamberVolume chamber{anatomy.cavities[c].name, -HUGE_VAL, HUGE_VAL};
    for (int i : beat) chamber.largest_ml = std::max(chamber.largest_ml, volumes[i][c]), chamber.smallest_ml = std::min(chamber.smallest_ml, volumes[i][c]);
    report.chambers.push_back(chamber);
  }
  int lv_cavity = 0;
  for (std::size_t c = 0; c < anatomy.cavities.size(); ++c) {
    if (anatomy.cavities[c].name == "left_ventricle") lv_cavity = static_cast<int>(c);
  }
  int ed = beat.front(), es = beat.front();
  for (int i : beat) {
    if (volumes[i][lv_cavity] > volumes[ed][lv_cavity]) ed = i;
    if (volumes[i][lv_cavity] < volumes[es][lv_cavity]) es = i;
  }
  // End-systole is the first frame after the aortic valve's closure or, where the valves are
  // not timed, the smallest volume's (Lang et al. 2015, "Chamber quantification"). With blood
  // the volume stays at its least through the isovolumic relaxation, so its smallest frame
  // could be any of them, the muscle already relaxing in the later ones.
  const double start = report.measured_from_s;
  if (!rec.step_times.empty() && !std::isnan(aortic_closes_ms)) {
    for (int i : beat) {
      if (1000 * (rec.times[i] - start) < aortic_closes_ms) continue;
      es = i;
      break;
    }
  }
  report.end_diastolic_ml = volumes[ed][lv_cavity];
  report.end_systolic_ml = volumes[es][lv_cavity];
  report.ejection_fraction_pct = 100 * (report.end_diastolic_ml - report.end_systolic_ml) / report.end_diastolic_ml;
  report.end_systole_ms = 1000 * (rec.times[es] - start);
  return {ed, es};
}

/// Each mid-ventricular segment's time to peak thickening over the measured beat, at every
/// step, and the septum's (AHA 8, 9) lead over the lateral wall (11, 12).
void segment_peaks(const HeartRecording& rec, PhysiologyReport& report) {
  const double start = report.measured_from_s;
  for (SegmentThickening& seg : report.segments) {
    const std::size_t s = static_cast<std::size_t>(seg.segment - 7);
    double thickest = -HUGE_VAL;
    for (std::size_t i = 0; i < rec.wall_times.size(); ++i) {
      const double t = rec.wall_times[i];
      if (t < start - 1e-9 || t >= start + report.beat_s - 1e-9 || rec.mid_thickness[i][s] <= thickest) continue;
      thickest = rec.mid_thickness[i][s];
      seg.peak_ms = 1000 * (t - start);
    }
  }
  const auto peak = [&](int segment) {
    for (const SegmentThickening& seg : report.segments) {
      if (seg.segment == segment) return seg.peak_ms;
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  report.septal_lateral_delay_ms = (peak(11) + peak(12)) / 2 - (peak(8) + peak(9)) / 2;
}

/// The left ventricle's shape from end-diastole `ed` to end-systole `es`: long-axis
/// shortening, wall and segment thickening; and over the beat, twist and muscle volume.
void measure_shape(const mesh::Anatomy& anatomy, const HeartRecording& rec, const std::vector<int>& beat, int ed, int es,
                   PhysiologyReport& report) {
  const std::vector<Eigen::Matrix3Xd>& shapes = rec.shapes;
  const mesh::VentricleLandmarks& lv = anatomy.left_ventricle;
  auto long_axis = [&](const Eigen::Matrix3Xd& s) { return (s.col(lv.apex) - centroid(lv.annulus, s)).norm(); };
  auto thickness = [&](const Eigen::Matrix3Xd& s) {
    double sum = 0;
    for (const auto& [inner, outer] : lv.wall) sum += (s.col(outer) - s.col(inner)).norm();
    return sum / static_cast<double>(lv.wall.size());
  };
  report.long_axis_shortening_pct = 100 * (1 - long_axis(shapes[es]) / long_axis(shapes[ed]));
  report.wall_thickening_pct = 100 * (thickness(shapes[es]) / thickness(shapes[ed]) - 1);
  report.segments = segment_thickening(lv, shapes[ed], shapes[es]);
  segment_peaks(rec, report);
  // Twist: apical minus basal rotation at its peak over the beat, from the ventricles'
  // activation, as speckle tracking times it from the ECG's R wave (Notomi et al. 2005); the
  // largest volume's frame can fall a frame or two either side of it.
  const double to_deg = 180 / std::numbers::pi;
  report.twist_deg = -HUGE_VAL;
  const Eigen::Matrix3Xd& activation = shapes[beat.front()];
  const double muscle0 = muscle_volume(anatomy.muscle, shapes[ed]);
  for (int i : beat) {
    const Eigen::Vector3d axis = (shapes[i].col(lv.apex) - centroid(lv.annulus, shapes[i])).normalized();
    const double apical = to_deg * ring_rotation(lv.apical_ring, activation, shapes[i], axis);
    const double basal = to_deg * ring_rotation(lv.basal_ring, activation, shapes[i], axis);
    if (apical - basal > report.twist_deg) {
      report.twist_deg = apical - basal;
      report.apical_rotation_deg = apical;
      report.basal_rotation_deg = basal;
    }
    report.muscle_volume_change_pct =
        std::max(report.muscle_volume_change_pct, 100 * std::abs(muscle_volume(anatomy.muscle, shapes[i]) / muscle0 - 1));
  }
}

/// When the ventricles' contraction starts after the beat's: the left ventricle's delay, or
/// with a conduction system the first ventricular muscle's excitation. unit: s
double ventricles_activate_s(const sim::Model& model, const sim::RegionParams& ventricle) {
  if (!model.excitation) return ventricle.drive.delay_s;
  const electro::Excitation& ex = *model.excitation;
  double first = HUGE_VAL;
  for (std::size_t i = 0; i < ex.tissue.size(); ++i) {
    if (ex.tissue[i] == electro::Tissue::kVentricle && !std::isnan(ex.activation_s[i])) first = std::min(first, ex.activation_s[i]);
  }
  return first;
}

/// The measured beat's ECG (from its sinus firing to the next one's) and its QRS onset to
/// the mitral valve's closure.
void measure_ecg(const world::OrganBody& body, int settle_beats, PhysiologyReport& report) {
  const double beat_start = settle_beats * report.beat_s;
  const std::optional<electro::Ecg> ecg = world::organ_ecg(body, beat_start + 2 * report.beat_s);
  // A little before the sinus node fires: the P wave's onset is at it.
  const double lead_in = 0.02;
  report.ecg = electro::measure_beat(*ecg, beat_start - lead_in, beat_start + report.beat_s - lead_in, report.beat_s);
  report.has_ecg = true;
  for (const ValveEvent& e : report.valve_events) {
    if (e.valve != "mitral_valve" || e.opens) continue;
    const double closes_s = report.measured_from_s + e.after_activation_ms / 1000;
    report.electromechanical_delay_ms = 1000 * (closes_s - report.ecg.qrs_onset_s);
    break;
  }
}

}  // namespace

PhysiologyReport measure_physiology(const scene::Scene& scene, int settle_beats) {
  world::FrameSource source(scene);
  // The beat is found in organ time from 0, whatever part of it the clip shows (a loop
  // starts after its settling beats: output.start_frame).
  source.world().start_frame = 0;
  const world::World& world = source.world();
  PhysiologyReport report;
  report.scene = scene.path;
  const int organ = anatomical_organ(scene, world);
  const world::OrganBody& body = world.organs[static_cast<std::size_t>(organ)];
  report.organ = body.model.name;
  const sim::RegionParams& ventricle = left_ventricle_drive(scene, body.model);
  report.beat_s = 1.0 / ventricle.drive.rate_hz;
  report.frame_s = world.frame_s;
  report.measured_from_s = settle_beats * report.beat_s + ventricles_activate_s(body.model, ventricle);
  const mesh::Anatomy& anatomy = body.geometry.mesh.anatomy;

  // One frame before the beat to one after it: the valves need the flow on both sides.
  const int first = static_cast<int>(std::floor(report.measured_from_s / world.frame_s)) - 1;
  const int last = static_cast<int>(std::ceil((report.measured_from_s + report.beat_s) / world.frame_s)) + 1;
  const HeartRecording rec = record_heart(source, organ, first, last);
  const std::vector<int> beat = beat_frames(rec.times, report.measured_from_s, report.beat_s);
  if (beat.size() < 2) {
    throw Error(ExitCode::kUsage, scene.path + ": --physiology samples a beat at the scene's frames, and frames " +
                                      std::to_string(world.frame_s) + " s apart leave fewer than two in a beat of " +
                                      std::to_string(report.beat_s) + " s; raise output.fps");
  }
  const double aortic_closes = measure_valves(anatomy, body, rec, report);
  const auto [ed, es] = measure_volumes(anatomy, rec, beat, aortic_closes, report);
  measure_shape(anatomy, rec, beat, ed, es, report);
  if (body.model.excitation) measure_ecg(body, settle_beats, report);
  return report;
}

namespace {

/// The computed ECG's figures, each against its normal range.
std::string ecg_text(const PhysiologyReport& r) {
  std::string out = "  computed ECG (the measured beat):\n";
  char line[256];
  const electro::BeatMeasures& e = r.ecg;
  const auto figure = [&](const char* name, double value, const char* unit, const NormalRange& range) {
    std::snprintf(line, sizeof line, "    %-24s %7.1f %-4s normal %g-%g %s (%s)\n", name, value, unit, range.low, range.high,
                  range.holds(value) ? "  " : "!!", range.source);
    out += line;
  };
  figure("PR interval", 1000 * e.pr_s, "ms", kPrInterval);
  figure("QRS duration", 1000 * e.qrs_s, "ms", kQrsDuration);
  std::snprintf(line, sizeof line, "    %-24s %7.1f ms\n", "QT interval", 1000 * e.qt_s);
  out += line;
  figure("QTc (Bazett)", 1000 * e.qtc_s, "ms", kQtc);
  figure("frontal QRS axis", e.axis_deg, "deg", kQrsAxis);
  figure("R/S transition (V1-V6)", e.transition, "", kTransition);
  if (std::isnan(r.electromechanical_delay_ms)) {
    out += "    electromechanical delay  not measured (the mitral valve does not close in the beat)\n";
  } else {
    figure("QRS onset to mitral close", r.electromechanical_delay_ms, "ms", kElectromechanicalDelay);
  }
  return out;
}

/// The mid-ventricular segments: each one's thickening and time to peak thickening, and the
/// septum's lead over the lateral wall.
std::string segments_text(const PhysiologyReport& r) {
  std::string out = "    mid-ventricular segments' thickening (AHA 7-12; below 10 % akinetic):";
  char line[256];
  for (const auto& seg : r.segments) {
    std::snprintf(line, sizeof line, " %s %.0f %%%s", seg.name, seg.thickening_pct, seg.akinetic() ? " (akinetic)" : "");
    out += line;
  }
  out += "\n    time to peak thickening (ms after activation):";
  for (const auto& seg : r.segments) {
    std::snprintf(line, sizeof line, " %s %.0f", seg.name, seg.peak_ms);
    out += line;
  }
  std::snprintf(line, sizeof line, "\n    septal (AHA 8, 9) to lateral (11, 12) delay %.0f ms%s\n", r.septal_lateral_delay_ms,
                std::abs(r.septal_lateral_delay_ms) >= kDyssynchronyDelayMs ? " (dyssynchronous: 60 ms or more, Bax 2003)" : "");
  return out + line;
}

}  // namespace

std::string physiology_text(const PhysiologyReport& r) {
  std::string out;
  char line[256];
  auto figure = [&](const char* name, double value, const char* unit, const NormalRange& range) {
    if (std::isnan(value)) {
      std::snprintf(line, sizeof line, "  %-26s not measured (normal %g-%g %s)\n", name, range.low, range.high, unit);
    } else {
      std::snprintf(line, sizeof line, "  %-26s %7.1f %-4s normal %g-%g %s (%s)\n", name, value, unit, range.low, range.high,
                    range.holds(value) ? "  " : "!!", range.source);
    }
    out += line;
  };
  std::snprintf(line, sizeof line, "physiology of %s in %s: beat %.0f ms, measured from %.3f s (the %s's activation), sampled every %.1f ms\n",
                r.organ.c_str(), r.scene.c_str(), 1000 * r.beat_s, r.measured_from_s, "left ventricle", 1000 * r.frame_s);
  out += line;
  out += "  chamber volumes (largest -> smallest, emptied):\n";
  for (const auto& c : r.chambers) {
    std::snprintf(line, sizeof line, "    %-18s %6.1f -> %5.1f ml  %4.1f %%\n", c.name.c_str(), c.largest_ml, c.smallest_ml, c.emptied_pct());
    out += line;
  }
  out += "  left ventricle:\n";
  figure("end-diastolic volume", r.end_diastolic_ml, "ml", kEndDiastolicVolume);
  figure("end-systolic volume", r.end_systolic_ml, "ml", kEndSystolicVolume);
  figure("ejection fraction", r.ejection_fraction_pct, "%", kEjectionFraction);
  figure("long-axis shortening", r.long_axis_shortening_pct, "%", kLongAxisShortening);
  figure("wall thickening", r.wall_thickening_pct, "%", kWallThickening);
  out += segments_text(r);
  figure("twist", r.twist_deg, "deg", kTwist);
  std::snprintf(line, sizeof line, "    (apex %+.1f deg, base %+.1f deg, anticlockwise seen from the apex; end-systole %.0f ms after activation)\n",
                r.apical_rotation_deg, r.basal_rotation_deg, r.end_systole_ms);
  out += line;
  figure("ejection (aortic open)", r.ejection_pct, "%", kEjectionShare);
  figure("isovolumic relaxation", r.isovolumic_relaxation_ms, "ms", kIsovolumicRelaxation);
  std::snprintf(line, sizeof line, "  myocardial volume varies by %.1f %% over the beat\n", r.muscle_volume_change_pct);
  out += line;
  out += "  valve events (ms after the left ventricle's activation):\n";
  for (const auto& e : r.valve_events) {
    std::snprintf(line, sizeof line, "    %6.0f ms  %s %s\n", e.after_activation_ms, e.valve.c_str(), e.opens ? "opens" : "closes");
    out += line;
  }
  if (r.has_ecg) out += ecg_text(r);
  const auto outside = r.outside_normal();
  if (outside.empty()) {
    out += "  every figure within its normal range\n";
  } else {
    out += "  outside the normal range:";
    for (std::size_t i = 0; i < outside.size(); ++i) out += (i ? ", " : " ") + outside[i];
    out += "\n";
  }
  return out;
}

}  // namespace systole::study
