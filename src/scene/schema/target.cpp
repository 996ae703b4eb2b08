// The training target's table (`organs[].target`, train/): where its motion comes from,
// how it is laid on the organ, and how the tuner may change the drives to follow it.

#include <algorithm>
#include <filesystem>

#include "common/input_file.h"
#include "scene/schema/parts.h"
#include "scene/tree.h"

namespace systole::scene::schema {
namespace {

ValueSpec<TargetFrame> frame_spec() {
  return map<TargetFrame>(
      {
          field("file", path_text(), &TargetFrame::file,
                "Mesh file with the organ's vertices in the same order, in the organ mesh's units and frame.")
              .required(),
          field("time", quantity(Dimension::kTime, closed(0, 3600)), &TargetFrame::time_s,
                "Time of this key within the period.")
              .required(),
      },
      [](const Node& node, TargetFrame& f, const std::string& path, const Context& ctx) {
        const std::filesystem::path file =
            std::filesystem::path(f.file).is_absolute() ? std::filesystem::path(f.file) : ctx.base_dir / f.file;
        if (const auto reason = unreadable_file_reason(file)) {
          throw Error(ExitCode::kNoInput, where(origin_of(node, "file")) + join(path, "file") + ": key-frame file " +
                                              file.lexically_normal().string() + " is " + *reason);
        }
        f.file = file.lexically_normal().string();
      });
}

ValueSpec<TargetCurve> curve_spec() {
  auto samples = list(number(open_closed(0, 10)), 2, 1024, "list of numbers");
  return map<TargetCurve>(
      {
          field("region", name_text(), &TargetCurve::region, "The region whose size the curve gives.").required(),
          field("scale", samples, &TargetCurve::samples,
                "Linear size relative to rest over one period, evenly spaced."),
          field<TargetCurve, std::vector<double>>(
              "volume", samples,
              [](TargetCurve& c) -> std::vector<double>& {
                c.volume = true;
                return c.samples;
              },
              "Volume relative to rest over one period, evenly spaced (a ventricular volume curve)."),
      },
      [](const Node& node, TargetCurve& c, const std::string& path, const Context&) {
        c.origin = node.origin;
        if ((node.find("scale") != nullptr) == (node.find("volume") != nullptr))
          fail(node.origin, path, "a curve has exactly one of scale, volume");
      });
}

ValueSpec<TargetAlign> align_spec() {
  auto landmark = map<TargetLandmark>({
      field("target", vec3(Dimension::kNumber), &TargetLandmark::target,
            "The point on the target, in its file's own coordinates.")
          .required(),
      field("organ", vec3(Dimension::kLength), &TargetLandmark::organ_m, "The matching point on the organ, in the scene.")
          .required(),
  });
  return map<TargetAlign>({
      field("mode", choice<bool>({{"similarity", false}, {"affine", true}}), &TargetAlign::affine,
            "How the target may be mapped onto the organ: rigid motion and uniform scale, or any affine map."),
      field("landmarks", list(landmark, 3, 64, "list of landmark pairs"), &TargetAlign::landmarks,
            "Pairs of matching points (3 or more) that start the alignment."),
  });
}

/// One target's own checks: one source of motion, keys that apply to it, the animation file
/// readable, key-frame times within one period.
void check_target(const Node& node, Target& t, const std::string& path, const Context& ctx) {
  t.enabled = true;
  t.origin = node.origin;
  if (int(!t.frames.empty()) + int(!t.curves.empty()) + int(!t.animation.empty()) != 1)
    fail(node.origin, path, "expected exactly one of frames, curves, animation");
  for (const char* key : {"samples", "cycles", "piece", "align", "units"}) {
    if (node.find(key) != nullptr && t.animation.empty())
      fail(origin_of(node, key), join(path, key), "applies to an animation only");
  }
  if (!t.animation.empty()) {
    const std::filesystem::path file = std::filesystem::path(t.animation).is_absolute()
                                           ? std::filesystem::path(t.animation)
                                           : ctx.base_dir / t.animation;
    if (const auto reason = unreadable_file_reason(file)) {
      throw Error(ExitCode::kNoInput, where(origin_of(node, "animation")) + join(path, "animation") +
                                          ": animation file " + file.lexically_normal().string() + " is " + *reason);
    }
    t.animation = file.lexically_normal().string();
  }
  const double period_s = 1.0 / t.rate_hz;
  for (std::size_t i = 0; i < t.frames.size(); ++i) {
    const Origin& at = node.find("frames")->items[i].origin;
    if (i > 0 && t.frames[i].time_s <= t.frames[i - 1].time_s)
      fail(at, path + ".frames[" + std::to_string(i) + "].time", "times must increase");
    if (t.frames[i].time_s >= period_s)
      fail(at, path + ".frames[" + std::to_string(i) + "].time",
           "must lie within one period (" + format_quantity(period_s, Dimension::kTime) + " at this rate)");
  }
}

}  // namespace

ValueSpec<Target> target_spec() {
  return map<Target>(
      {
          field("rate", quantity(Dimension::kFrequency, open_closed(0, 20)), &Target::rate_hz,
                "Cycles per unit time of the target; the tuned drives run at it.")
              .required(),
          field("frames", list(frame_spec(), 2, 4096, "list of key frames"), &Target::frames,
                "Key-frame meshes at times within one period, interpolated smoothly and periodically."),
          field("curves", list(curve_spec(), 1, 256, "list of curves"), &Target::curves,
                "Per-region size curves over one period (instead of frames)."),
          field("animation", path_text(), &Target::animation,
                "An animated file of the organ, in any mesh: glTF/GLB, FBX, Collada... (its first animation: morph targets "
                "and/or skinning), a PC2 or MDD point cache with the OBJ of the same name beside it, or a ParaView series "
                "(.pvd). It is aligned to the organ and its motion transferred onto the organ's surface."),
          field("samples", whole<int>(4, 1024), &Target::animation_samples,
                "Poses sampled evenly from the animation over one period. Unset: a glTF's own keys where they are evenly "
                "spaced (a sampled clip, as `systole export` writes), else 32."),
          field("cycles", whole<int>(1, 10000), &Target::cycles,
                "Periods the animation holds (a clip of many beats, as `systole export --encoding frames` writes one): "
                "the one at the time the error is measured (after `settle`), or its last, is the target."),
          field("piece", whole<int>(0, 100000), &Target::piece,
                "Which piece of a ParaView series is this organ (a series holds one per organ, in the scene's order)."),
          field("units", choice<double>({{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}), &Target::unit_m,
                "The animation file's units, when they are not the organ mesh's."),
          field("align", align_spec(), &Target::align,
                "How an animation's rest surface is laid on the organ's (docs/training.md, \"A target of any mesh\")."),
          field("coupling", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Target::coupling_N_per_m,
                "Stiffness tying each particle to its target while the driving forces are recorded."),
          field("harmonics", whole<int>(1, 16), &Target::harmonics, "Fourier harmonics of each fitted drive."),
          field("lock", list(path_text(), 0, 1024, "list of names"), &Target::lock,
                "Parameters the tuner keeps as the scene writes them: `amplitude`, `shape`, `delay`, `stiffness` (all "
                "regions), a region's name (all its parameters), or `region.param`."),
          field("budget", whole<int>(0, 1000000), &Target::budget, "Playbacks the tuner may run (0: fit only)."),
          field("settle", number(closed(0, 100)), &Target::settle_cycles, "Cycles run before the error is measured."),
          field("measure", number(open_closed(0, 100)), &Target::measure_cycles,
                "Cycles over which the error is measured."),
      },
      check_target);
}

/// The target's region names and lock entries must name the organ's regions.
void check_target_names(const Node& node, const Organ& o, const std::string& path) {
  if (!o.target.enabled) return;
  const Node& target = *node.find("target");
  auto region = [&](const std::string& name) {
    return std::find_if(o.regions.begin(), o.regions.end(), [&](const Region& r) { return r.name == name; });
  };
  for (std::size_t i = 0; i < o.target.curves.size(); ++i) {
    const TargetCurve& c = o.target.curves[i];
    const auto r = region(c.region);
    if (r == o.regions.end())
      fail(c.origin, path + ".target.curves[" + std::to_string(i) + "].region",
           "the organ has no region '" + c.region + "'");
    if (r->pinned)
      fail(c.origin, path + ".target.curves[" + std::to_string(i) + "].region",
           "region '" + c.region + "' is pinned: it cannot follow a curve");
  }
  const std::vector<std::string> params = {"amplitude", "shape", "delay", "stiffness"};
  for (std::size_t i = 0; i < o.target.lock.size(); ++i) {
    const std::string& entry = o.target.lock[i];
    const std::size_t dot = entry.find('.');
    const std::string head = entry.substr(0, dot), param = dot == std::string::npos ? "" : entry.substr(dot + 1);
    const bool is_param = std::find(params.begin(), params.end(), head) != params.end() && dot == std::string::npos;
    const bool good = is_param || (region(head) != o.regions.end() &&
                                   (param.empty() || std::find(params.begin(), params.end(), param) != params.end()));
    if (!good)
      fail(target.find("lock")->items[i].origin, path + ".target.lock[" + std::to_string(i) + "]",
           "expected amplitude, shape, delay, stiffness, a region's name, or region.param with one of those; got '" +
               entry + "'");
  }
}

}  // namespace systole::scene::schema
