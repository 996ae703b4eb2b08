#include "study/summary.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "clip/render_detail.h"
#include "clip/video_format.h"
#include "mesh/inspect.h"
#include "scene/tree.h"
#include "sim/solvers/step_size.h"

namespace systole::study {
namespace {

/// Each region of an organ with its vertex count, pin and drive.
void summarize_regions(std::ostringstream& s, const scene::Organ& organ, const world::OrganBody& body) {
  std::vector<int> counts(organ.regions.size() + 1, 0);
  for (int r : body.geometry.vertex_region) ++counts[r + 1];
  if (counts[0] > 0) s << "  region (undriven body): " << counts[0] << " vertices\n";
  for (std::size_t r = 0; r < organ.regions.size(); ++r) {
    const auto& region = organ.regions[r];
    s << "  region " << region.name << ": " << counts[r + 1] << " vertices";
    if (region.pinned) s << ", pinned";
    if (region.drive.waveform != scene::Waveform::kNone) {
      s << ", drive " << region.drive.rate_hz * 60.0 << " per min, amplitude " << region.drive.amplitude;
      if (region.drive.delay_s != 0) s << ", delay " << region.drive.delay_s * 1e3 << " ms";
    }
    if (region.stiffness_scale != 1.0) s << ", stiffness x" << region.stiffness_scale;
    s << "\n";
  }
}

/// The mesh's parts, as a region's `part:` selector names them, with their triangles and
/// whether each is closed on its own: how a user finds what to drive and what to pin in a
/// file of many parts (a part that only touches others has no triangle of its own). Each
/// name is written as the scene must write it (quoted when YAML needs it), so any listed
/// name pasted after `part: ` selects that part.
void summarize_parts(std::ostringstream& s, const world::OrganBody& body) {
  const mesh::OrganMesh& m = body.geometry.mesh;
  if (m.part_names.empty()) return;
  s << "  parts (select with `part: NAME`):\n";
  const std::vector<mesh::TriangleMesh> surfaces = m.part_surfaces();
  for (std::size_t p = 0; p < m.part_names.size(); ++p) {
    const mesh::MeshReport r = mesh::inspect(surfaces[p]);
    s << "    " << scene::yaml_scalar(m.part_names[p]) << ": " << r.triangles << " triangles, " << (r.closed() ? "closed" : "open") << "\n";
  }
}

/// The constraints an organ's model was built with, what was left out, and what a step costs.
void summarize_model(std::ostringstream& s, const scene::Organ& organ, const world::OrganBody& body, double dt_s) {
  const auto& m = body.model;
  s << "  constraints: " << m.springs.stretch_count << " stretch springs, " << m.springs.bending_count
    << " bending springs (" << m.springs.colors() << " colours)";
  s << (m.volume.enabled ? ", 1 volume constraint" : ", no volume constraint");
  if (!m.pokes.empty() || !m.grabs.empty()) s << ", " << m.pokes.size() << " pokes, " << m.grabs.size() << " grabs";
  s << "\n";
  const auto pinned = (m.inverse_mass.array() == 0).count();
  s << "  built: " << m.particle_count() << " particles";
  if (body.embedding.empty()) {
    s << " (full model: every vertex)";
  } else {
    s << " (lattice " << body.lattice << ": voxel corners; the " << body.geometry.report.vertices
      << " render vertices follow by embedding)";
  }
  if (pinned > 0) s << ", " << pinned << " pinned (held, not solved; no spring between two of them)";
  s << "\n  body: " << body.body_reason;
  for (const sim::Chamber& chamber : m.circulation.chambers) {
    s << "\n  blood: " << chamber.name << ", " << std::round(chamber.rest_m3 * 1e7) / 10 << " ml at rest, held while its valves are shut; "
      << "its outflow valve opens at " << chamber.afterload_Pa / 1000 << " kPa, rising "
      << chamber.arterial_elastance_Pa_per_m3 * 1e-6 << " Pa per ml ejected";
  }
  s << "\n  left out:";
  int left_out = 0;
  if (m.springs.bending_count == 0) s << (left_out++ ? "," : "") << " bending (body.bending is 0)";
  if (!m.volume.enabled) {
    s << (left_out++ ? "," : "") << " volume constraint ("
      << (organ.body.volume_stiffness_Pa > 0 ? "the surface is open" : "body.volume_stiffness is 0") << ")";
  }
  if (body.embedding.empty()) s << (left_out++ ? "," : "") << " reduction (body.lattice is 0)";
  if (left_out == 0) s << " nothing";
  const double cost = sim::estimated_cost_s_per_s(m, dt_s);
  s << "\n  cost estimate: " << cost * 1e3 << " ms per simulated second on one thread ("
    << (cost > 0 ? 1.0 / cost : 0.0) << "x real time; `systole bench` measures)\n";
}

/// The video: format, size, frames, loop, cards and captions.
void summarize_output(std::ostringstream& s, const scene::Scene& scene) {
  const auto& out = scene.output;
  s << "output " << clip::default_video_path(scene).extension().string().substr(1) << ", " << out.width << "x" << out.height
    << ", " << out.fps << " fps, " << out.frame_count() << " frames (" << out.duration_s << " s of organ time";
  if (out.slow_motion != 1) {
    s << " at " << out.slow_motion << "x slow motion: " << out.frame_count() / out.fps << " s of video";
  }
  s << ")\n";
  if (out.loop) {
    s << "  loop: " << out.duration_s << " s, whole cycles of every drive; starts after " << out.start_frame
      << " settling frames (" << out.start_frame * out.frame_period_s() << " s)\n";
  }
  if (!scene.cards.empty() || !scene.captions.empty()) {
    double cards_s = 0;
    for (const auto& c : scene.cards) cards_s += c.duration_s;
    s << "  " << scene.cards.size() << " title card(s) (" << cards_s << " s, before the clip), "
      << scene.captions.size() << " caption(s)" << (out.burn_captions ? " burned in" : " not burned in") << "\n";
  }
  const bool gif = out.format == scene::Format::kGif;
  if (!scene.captions.empty()) {
    s << "  captions also as " << (gif ? "a .vtt file beside the GIF (a GIF holds no subtitle track)"
                                       : "a subtitle track and a .vtt file beside the video") << "\n";
  }
  if (!scene.chapters.empty() || !scene.cards.empty()) {
    s << "  " << scene.cards.size() + scene.chapters.size() << " chapter mark(s)"
      << (gif ? ": none written, a GIF has no chapters" : "") << "\n";
  }
  if (scene.audio.enabled) {
    const auto& a = scene.audio;
    std::vector<std::string> parts;
    if (a.heart.enabled) {
      std::string h = "heart sounds of " + a.heart.organ + " timed by";
      for (const auto& r : a.heart.regions) h += " " + r;
      h += std::string(", stethoscope at the ") + (a.heart.stethoscope == scene::Stethoscope::kApex ? "apex" : "base");
      if (a.heart.s3.enabled) h += ", S3";
      if (a.heart.murmur.enabled) h += ", a murmur";
      parts.push_back(h);
    }
    if (a.breath.enabled) parts.push_back("breath sounds of " + a.breath.organ);
    if (a.click.enabled) parts.push_back("a click at " + std::to_string(a.click.rate_hz * 60).substr(0, 5) + " /min");
    s << "  audio: ";
    for (std::size_t i = 0; i < parts.size(); ++i) s << (i ? "; " : "") << parts[i];
    s << (gif ? "; NOT in the video: a GIF has no sound (render --wav FILE writes it alone); PNG frames have none either"
              : "; PNG frames have no sound (render --wav FILE writes it alone)")
      << "\n";
  }
}

/// The overlay's parts in one line (nothing when the scene has none).
void summarize_overlay(std::ostringstream& s, const scene::Overlay& ov) {
  if (ov.empty()) return;
  std::vector<std::string> parts;
  if (!ov.title.empty()) parts.push_back("title \"" + ov.title + "\"");
  if (ov.labels.enabled) {
    const std::string which =
        ov.labels.regions.empty() ? std::string("every region") : std::to_string(ov.labels.regions.size()) + " regions";
    parts.push_back("labels of " + which + (ov.labels.organ.empty() ? "" : " of " + ov.labels.organ));
  }
  if (ov.legend.enabled) parts.push_back("legend of region colours");
  for (const auto& t : ov.traces) {
    std::ostringstream trace;
    const char* signal = t.signal == scene::TraceSignal::kVolume ? "volume"
                         : t.signal == scene::TraceSignal::kEcg  ? "ecg"
                                                                 : "activation";
    const std::string& of = t.chamber.empty() ? t.region : t.chamber;
    trace << signal << (of.empty() ? "" : " of " + of) << " trace (";
    if (t.window_s > 0) trace << t.window_s << " s sweep)";
    else trace << "whole clip)";
    parts.push_back(trace.str());
  }
  s << "overlay:";
  for (std::size_t i = 0; i < parts.size(); ++i) s << (i ? "; " : " ") << parts[i];
  s << " (docs/teaching-visuals.md)\n";
}

}  // namespace

std::string summarize(const scene::Scene& scene, const world::World& world) {
  std::ostringstream s;
  s << "scene " << scene.path << "\n";
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& organ = scene.organs[o];
    const auto& body = world.organs[o];
    const auto& report = body.geometry.report;
    s << "organ " << organ.name << ": " << report.vertices << " vertices, " << report.triangles << " triangles, "
      << (report.closed() ? "closed" : "open") << ", volume " << report.volume_m3 * 1e6 << " cm^3\n";
    for (const auto& note : report.notes) s << "  mesh: " << note << "\n";
    summarize_parts(s, body);
    summarize_regions(s, organ, body);
    summarize_model(s, organ, body, world.dt_s);
  }
  s << "solver " << scene::method_name(scene.solver.method) << ": dt " << world.dt_s * 1e3 << " ms ("
    << world.steps_per_frame << " steps per frame)";
  for (const auto& body : world.organs) s << ", " << body.model.name << " " << body.model.substeps << " substeps";
  s << "\n  why: " << world.step_reason << "\n";
  const auto& camera = scene.camera;
  s << "camera: " << (camera.automatic ? "frames the organs (no position given): " : "") << "at ("
    << camera.position_m.x() << ", " << camera.position_m.y() << ", " << camera.position_m.z() << ") m looking at ("
    << camera.target_m.x() << ", " << camera.target_m.y() << ", " << camera.target_m.z() << ") m\n";
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const clip::RenderDetail detail = clip::render_detail(scene, world, o);
    if (detail.full_triangles <= clip::kSimplifyFromTriangles) continue;
    s << "drawn: " << scene.organs[o].name << ": ";
    if (detail.pixel_m > 0) {
      s << detail.triangles.size() << " of " << detail.full_triangles
        << " triangles, simplified within a pixel (a pixel is " << detail.pixel_m * 1e3
        << " mm on the organ at the nearest camera; the removed vertices lie within " << detail.error_m * 1e3
        << " mm of the drawn surface); " << detail.triangles.size() - detail.two_sided_from
        << " of them in open pieces, drawn two-sided\n";
    } else {
      s << "all " << detail.full_triangles << " triangles (a camera comes inside the organ's bounding sphere)\n";
    }
  }
  summarize_output(s, scene);
  summarize_overlay(s, scene.overlay);
  return s.str();
}

}  // namespace systole::study
