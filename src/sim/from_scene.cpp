#include "sim/from_scene.h"

namespace systole::sim {
namespace {

/// "file:line:column" of a scene entry, or "" when it came from no file.
std::string where(const scene::Origin& at) {
  if (at.file.empty()) return "";
  return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

InteractionParams interaction_params(const scene::Interaction& in, std::size_t index) {
  InteractionParams p;
  p.kind = in.kind;
  p.where = where(in.origin);
  p.key = "interactions[" + std::to_string(index) + "]." + (p.kind == InteractionKind::kGrab ? "grab" : "poke");
  p.at_m = in.at_m;
  p.radius_m = in.radius_m;
  p.force_N = in.force_N;
  p.start_s = in.start_s;
  p.duration_s = in.duration_s;
  p.drive = in.drive;
  p.path = in.path;
  p.stiffness_N_per_m = in.stiffness_N_per_m;
  return p;
}

}  // namespace

Method method_params(scene::SolverMethod method) {
  switch (method) {
    case scene::SolverMethod::kXpbd: return Method::kXpbd;
    case scene::SolverMethod::kExplicit: return Method::kExplicit;
    case scene::SolverMethod::kImplicit: return Method::kImplicit;
    case scene::SolverMethod::kProjective: return Method::kProjective;
  }
  return Method::kXpbd;
}

RegionParams region_params(const scene::Region& r) {
  RegionParams p{r.name, r.drive, r.stiffness_scale, r.damping_scale, r.pinned, r.detail, r.motion};
  if (r.tether.enabled) {
    p.tether_stiffness_N_per_m = r.tether.stiffness_N_per_m;
    p.tether_offset_m = r.tether.offset_m;
  }
  return p;
}

std::vector<RegionParams> region_params(const std::vector<scene::Region>& regions) {
  std::vector<RegionParams> out;
  out.reserve(regions.size());
  for (const auto& r : regions) out.push_back(region_params(r));
  return out;
}

OrganParams organ_params(const scene::Organ& organ) {
  OrganParams p;
  p.name = organ.name;
  p.where = organ.origin.file.empty() ? "" : where(organ.origin) + ": ";
  const scene::Body& b = organ.body;
  p.body = {b.mass_kg, b.stiffness_N_per_m, b.damping_s, b.volume_stiffness_Pa, b.drag_per_s,
            b.bending_N_per_m, b.lattice, b.volume_drive, b.fibre_tension};
  const scene::Blood& blood = organ.blood;
  p.blood.enabled = blood.enabled;
  p.blood.aortic_Pa = blood.aortic_pressure_Pa;
  p.blood.pulmonary_Pa = blood.pulmonary_pressure_Pa;
  p.blood.aortic_elastance_Pa_per_m3 = blood.aortic_elastance_Pa_per_m3;
  p.blood.pulmonary_elastance_Pa_per_m3 = blood.pulmonary_elastance_Pa_per_m3;
  p.blood.filling_Pa = blood.filling_pressure_Pa;
  p.blood.chordae = blood.chordae;
  p.electrophysiology = organ.electrophysiology.enabled;
  p.conduction.block = organ.electrophysiology.block == scene::BundleBranchBlock::kLeft    ? electro::Block::kLeftBundle
                       : organ.electrophysiology.block == scene::BundleBranchBlock::kRight ? electro::Block::kRightBundle
                                                                                            : electro::Block::kNone;
  p.regions = region_params(organ.regions);
  return p;
}

ModelOptions model_options(const scene::Scene& scene, const std::string& organ_name, double dt_s) {
  ModelOptions options;
  options.solver = {method_params(scene.solver.method), scene.solver.substeps, scene.solver.iterations,
                    scene.solver.threads, scene.solver.auto_dt};
  options.dt_s = dt_s;
  options.gravity = scene.gravity;
  const double frame_s = scene.output.frame_period_s();
  options.clip_s = scene.output.start_frame * frame_s + scene.output.duration_s;  // Organ time at the clip's end.
  options.seed = scene.seed;
  options.floor = scene.floor;
  for (std::size_t i = 0; i < scene.interactions.size(); ++i) {
    if (scene.interactions[i].organ == organ_name) options.interactions.push_back(interaction_params(scene.interactions[i], i));
  }
  return options;
}

contact::Params contact_params(const scene::Scene& scene) {
  contact::Params out;
  const scene::Contact& c = scene.contact;
  out.iterations = c.iterations;
  out.threads = scene.solver.threads;
  const auto index = [&](const std::string& name) {
    for (std::size_t i = 0; i < scene.organs.size(); ++i)
      if (scene.organs[i].name == name) return static_cast<int>(i);
    return -1;
  };
  if (c.pairs.empty()) {
    for (std::size_t a = 0; a < scene.organs.size(); ++a)
      for (std::size_t b = a + 1; b < scene.organs.size(); ++b) {
        if (scene.organs[a].collider && scene.organs[b].collider) continue;
        out.pairs.push_back({static_cast<int>(a), static_cast<int>(b), c.thickness_m, c.friction});
      }
    return out;
  }
  for (const scene::ContactPair& p : c.pairs) {
    out.pairs.push_back({index(p.organs[0]), index(p.organs[1]), p.has_thickness ? p.thickness_m : c.thickness_m,
                         p.has_friction ? p.friction : c.friction});
  }
  return out;
}

}  // namespace systole::sim
