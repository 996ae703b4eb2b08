// The organ tables: mesh, transform, material, regions (selectors, drives); the target is
// in target.cpp, the body and the blood in body.cpp.

#include "scene/schema/parts.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "common/input_file.h"
#include "scene/tree.h"

namespace systole::scene::schema {
namespace {

// The shapes a selector may name, one field table each.
ValueSpec<Selector> sphere_spec() {
  return map<Selector>({
      field("center", vec3(Dimension::kLength), &Selector::center,
            "Centre, in organ space (after units and centring)."),
      field("radius", quantity(Dimension::kLength, open_closed(0, 1000)), &Selector::radius_m, "Radius.").required(),
  });
}

ValueSpec<Selector> box_spec() {
  return map<Selector>(
      {
          field("min", vec3(Dimension::kLength), &Selector::min, "Lowest corner, in organ space.").required(),
          field("max", vec3(Dimension::kLength), &Selector::max, "Highest corner, in organ space.").required(),
      },
      [](const Node& node, Selector& s, const std::string& path, const Context&) {
        if ((s.min.array() > s.max.array()).any())
          fail(origin_of(node, "max"), join(path, "max"), "every coordinate of max must be >= that of min");
      });
}

ValueSpec<Selector> half_space_spec() {
  return map<Selector>(
      {
          field("point", vec3(Dimension::kLength), &Selector::point, "A point on the boundary plane."),
          field("normal", direction(), &Selector::normal, "Points into the selected side (normalised on reading).")
              .required(),
      },
      [](const Node&, Selector& s, const std::string&, const Context&) { s.normal.normalize(); });
}

ValueSpec<Selector> selector_map() {
  auto sphere = sphere_spec();
  auto box = box_spec();
  auto half_space = half_space_spec();

  return map<Selector>(
      {
          field<Selector, std::string>(
              "part", part_text(),
              [](Selector& s) -> std::string& {
                s.kind = SelectorKind::kPart;
                return s.part;
              },
              "A named part, written as `systole validate` lists it: a procedural organ's anatomical part, or a "
              "mesh file's mesh, node or material (`heart/left_atrium` also by its last segments, `left_atrium`, when "
              "no other part ends so).")
              .shown_default("—"),
          field<Selector, Selector>(
              "sphere", sphere,
              [](Selector& s) -> Selector& {
                s.kind = SelectorKind::kSphere;
                return s;
              },
              "Vertices within `radius` of `center`."),
          field<Selector, Selector>(
              "box", box,
              [](Selector& s) -> Selector& {
                s.kind = SelectorKind::kBox;
                return s;
              },
              "Vertices inside the axis-aligned box."),
          field<Selector, Selector>(
              "half_space", half_space,
              [](Selector& s) -> Selector& {
                s.kind = SelectorKind::kHalfSpace;
                return s;
              },
              "Vertices on the `normal` side of the plane through `point`."),
      },
      [](const Node& node, Selector& s, const std::string& path, const Context&) {
        if (node.entries.size() != 1)
          fail(node.origin, path,
               "a selector has exactly one of part, sphere, box, half_space; got " +
                   std::to_string(node.entries.size()) + " keys");
        // A part is resolved only once the mesh is read: its errors point at the name, which
        // a -D may have given in place of the file's.
        const Node* part = node.find("part");
        s.origin = part ? part->origin : node.origin;
      });
}

/// `select`: "all", one selector map, or a list of them (their union).
ValueSpec<std::vector<Selector>> selection() {
  const ValueSpec<Selector> one = selector_map();
  ValueSpec<std::vector<Selector>> spec;
  spec.type = "selector or list";
  spec.range = "`all`, a selector map, or a list of these";
  spec.keys = one.keys;
  auto read_one = [one](const Node& node, const std::string& path, const Context& ctx) {
    Selector s;
    if (node.kind == Node::Kind::kScalar && node.scalar == "all") {
      s.origin = node.origin;
      return s;
    }
    if (node.kind != Node::Kind::kMap)
      fail(node.origin, path,
           "expected \"all\" or a selector map (part, sphere, box or half_space); got " + node.describe());
    one.read(node, s, path, ctx);
    return s;
  };
  spec.read = [read_one](const Node& node, std::vector<Selector>& out, const std::string& path, const Context& ctx) {
    out.clear();
    if (node.kind == Node::Kind::kList) {
      if (node.items.empty()) fail(node.origin, path, "expected at least one selector; got an empty list");
      for (std::size_t i = 0; i < node.items.size(); ++i)
        out.push_back(read_one(node.items[i], path + "[" + std::to_string(i) + "]", ctx));
    } else {
      out.push_back(read_one(node, path, ctx));
    }
  };
  spec.show = [](const std::vector<Selector>&) { return std::string("the part named like the region"); };
  return spec;
}

/// Two numbers [lo, hi] with lo < hi.
ValueSpec<Eigen::Vector2d> value_pair() {
  ValueSpec<Eigen::Vector2d> spec;
  spec.type = "2 numbers";
  spec.range = "[lo, hi], lo < hi";
  spec.read = [](const Node& node, Eigen::Vector2d& out, const std::string& path, const Context&) {
    if (node.kind != Node::Kind::kList || node.items.size() != 2)
      fail(node.origin, path, "expected a list of 2 numbers [lo, hi]; got " + node.describe());
    for (int i = 0; i < 2; ++i)
      out[i] = parse_quantity(node.items[i], Dimension::kNumber, path + "[" + std::to_string(i) + "]");
    if (!(out[0] < out[1]))
      fail(node.origin, path, "expected lo < hi; got [" + format_number(out[0]) + ", " + format_number(out[1]) + "]");
  };
  spec.show = [](const Eigen::Vector2d& v) { return "[" + format_number(v[0]) + ", " + format_number(v[1]) + "]"; };
  return spec;
}

/// `tether`: zero-length springs of a region's particles to their rest places (+ offset).
ValueSpec<Tether> tether_spec() {
  return map<Tether>(
      {
          field("stiffness", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Tether::stiffness_N_per_m,
                "Stiffness of the whole region's hold, shared evenly by its particles.")
              .required(),
          field("offset", vec3(Dimension::kLength), &Tether::offset_m,
                "Where the anchor lies from the rest place: a preload, e.g. the heart pulled onto the diaphragm."),
      },
      [](const Node&, Tether& t, const std::string&, const Context&) { t.enabled = true; });
}

/// A region's name is a word (name_text): it is a -D path segment, a report's file name and a
/// label. A part's name is any text, so a region named like a nested part is told how to
/// take that part instead.
ValueSpec<std::string> region_name() {
  ValueSpec<std::string> spec = name_text();
  spec.read = [word = spec.read](const Node& node, std::string& out, const std::string& path, const Context& ctx) {
    const std::string& s = node.scalar;
    if (node.kind == Node::Kind::kScalar && s.find('/') != std::string::npos && s.back() != '/') {
      const std::string last = s.substr(s.rfind('/') + 1);
      const bool last_is_word = std::all_of(last.begin(), last.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      });
      fail(node.origin, path,
           "a name may use only letters, digits, '_' and '-' (it is a -D path segment and a file name); got " +
               node.describe() + ". To take the part " + node.describe() + ", " +
               (last_is_word ? "name the region " + last + " (a name selects the one part whose name ends in /" +
                                   last + ") or " : std::string()) +
               "give the region any name and select: {part: " + yaml_scalar(s) + "}");
    }
    word(node, out, path, ctx);
  };
  return spec;
}

ValueSpec<Region> region_spec() {
  return map<Region>(
      {
          field("name", region_name(), &Region::name,
                "Unique within the organ; also the default part to select (the part of that name, or the one part "
                "whose name ends in /NAME).")
              .required(),
          field("select", selection(), &Region::select,
                "Which vertices belong to the region (a list is a union); later regions take vertices from earlier "
                "ones."),
          field("drive", drive_spec(), &Region::drive,
                "The region's rhythm: L(t) = L0 (1 - amplitude phi(t - delay))."),
          field("stiffness", number(open_closed(0, 1e6)), &Region::stiffness_scale, "Multiplies the body's stiffness."),
          field("damping", number(closed(0, 1e6)), &Region::damping_scale, "Multiplies the body's damping."),
          field("pinned", boolean(), &Region::pinned, "Fixed in place (valves, vessel stumps)."),
          field("detail", choice<int>({{"1", 1}, {"2", 2}, {"4", 4}}), &Region::detail,
                "Reduced model (`body.lattice`) only: the region's voxels are split into detail^3, so it keeps more "
                "detail."),
          field("motion", path_keys("Offset of the region from its rest position."), &Region::motion,
                "Pinned regions: a prescribed motion (a kinematic region), smoothly interpolated, held after the last "
                "key."),
          field("tether", tether_spec(), &Region::tether,
                "A compliant hold towards the region's rest place (ligaments, the mediastinum), beside rigid `pinned`: "
                "contact and drives can still move it (docs/contact.md).")
              .shown_default("none"),
          field<Region, Color>(
              "color", color(),
              [](Region& r) -> Color& {
                r.has_color = true;
                return r.color;
              },
              "Colour of the region; else the organ's material colour.")
              .shown_default("material color"),
          field<Region, double>(
              "opacity", number(closed(0, 1)),
              [](Region& r) -> double& {
                r.has_opacity = true;
                return r.opacity;
              },
              "Opacity of the region; else the material's.")
              .shown_default("material opacity"),
      },
      [](const Node& node, Region& r, const std::string& path, const Context&) {
        r.origin = node.origin;
        if (r.tether.enabled && r.pinned)
          fail(origin_of(node, "tether"), join(path, "tether"),
               "a pinned region is held rigidly already; give it pinned or tether, not both");
        if (!r.motion.empty() && !r.pinned)
          fail(origin_of(node, "motion"), join(path, "motion"),
               "a prescribed motion needs pinned: true (the region is moved, not simulated)");
      });
}

ValueSpec<MeshSource> mesh_spec() {
  return map<MeshSource>(
      {
          field("file", path_text(), &MeshSource::file,
                "Mesh file (OBJ, STL, PLY, glTF, ...), relative to the scene's folder."),
          field("procedural", name_text(), &MeshSource::procedural, "A generated organ, e.g. `heart`."),
          field("detail", whole<int>(1, 6), &MeshSource::detail,
                "`procedural` only: level of detail, 1 (coarse) to 6 (fine)."),
          field("units", choice<double>({{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}), &MeshSource::unit_m,
                "`file` only: the file's length unit."),
          field("center", boolean(), &MeshSource::center, "Move the mesh's bounding-box centre to the origin."),
      },
      [](const Node& node, MeshSource& m, const std::string& path, const Context& ctx) {
        m.origin = node.origin;
        if (node.find("units") != nullptr) m.units_origin = origin_of(node, "units");
        const bool has_file = node.find("file") != nullptr, has_procedural = node.find("procedural") != nullptr;
        if (has_file == has_procedural)
          fail(node.origin, path,
               std::string("expected exactly one of file, procedural; got ") + (has_file ? "both" : "neither"));
        if (has_file && node.find("detail"))
          fail(origin_of(node, "detail"), join(path, "detail"), "applies only to a procedural mesh");
        if (has_procedural && node.find("units"))
          fail(origin_of(node, "units"), join(path, "units"), "applies only to a mesh file");
        if (has_file) {
          const std::filesystem::path file =
              std::filesystem::path(m.file).is_absolute() ? std::filesystem::path(m.file) : ctx.base_dir / m.file;
          if (const auto reason = unreadable_file_reason(file)) {
            throw Error(ExitCode::kNoInput, where(origin_of(node, "file")) + join(path, "file") + ": mesh file " +
                                                file.lexically_normal().string() + " is " + *reason);
          }
          m.file = file.lexically_normal().string();
        }
      });
}

/// `target`: the motion `systole tune` fits the organ's regions to (train/).
}  // namespace

ValueSpec<Drive> drive_spec() {
  auto harmonic = map<Harmonic>({
      field("amplitude", number(closed(0, 0.5)), &Harmonic::amplitude, "Weight of this harmonic in phi."),
      field("phase", quantity(Dimension::kAngle, any()), &Harmonic::phase_rad, "Phase of this harmonic."),
  });
  auto rate = quantity(Dimension::kFrequency, closed(0, 20));
  return map<Drive>(
      {
          field("waveform",
                choice<Waveform>({{"none", Waveform::kNone},
                                  {"sine", Waveform::kSine},
                                  {"fourier", Waveform::kFourier},
                                  {"cardiac", Waveform::kCardiac},
                                  {"breathing", Waveform::kBreathing},
                                  {"samples", Waveform::kSamples}}),
                &Drive::waveform, "Shape of phi(t) over one period; `none` leaves the region passive."),
          field("rate", rate, &Drive::rate_hz, "Cycles per unit time at the start of the clip (72 bpm = 1.2 Hz)."),
          field("rate_end", rate, &Drive::rate_end_hz, "When > 0, the rate ramps linearly to this by the clip's end."),
          field("amplitude", number(closed(0, 0.95)), &Drive::amplitude, "Fraction of rest length removed at phi = 1."),
          field("phase", quantity(Dimension::kAngle, any()), &Drive::phase_rad, "Phase offset of the cycle."),
          field("delay", quantity(Dimension::kTime, closed(0, 60)), &Drive::delay_s,
                "Activation delay (atria before ventricles)."),
          field("systolic_fraction", number(open(0.05, 0.95)), &Drive::systolic_fraction,
                "`cardiac`: part of the period spent contracting."),
          field("peak_fraction", number(open(0.05, 0.95)), &Drive::peak_fraction,
                "`cardiac`: where in its systolic part the contraction peaks (0.5: a symmetric pulse; "
                "higher: a slow shortening and a quick relaxation, as myocardial strain goes)."),
          field("inhale_fraction", number(open(0.05, 0.95)), &Drive::inhale_fraction,
                "`breathing`: part of the period spent inhaling."),
          field("harmonics", list(harmonic, 0, 32, "list of harmonics"), &Drive::harmonics,
                "`fourier`: harmonic k = 1, 2, ... as {amplitude, phase}; amplitudes sum to at most 0.5."),
          field("samples", list(number(closed(0, 1)), 2, 1024, "list of numbers"), &Drive::samples,
                "`samples`: phi over one period, evenly spaced, interpolated periodically."),
          field("irregularity", number(closed(0, 0.5)), &Drive::irregularity,
                "Seeded beat-to-beat jitter of the period (0 = regular)."),
      },
      [](const Node& node, Drive& d, const std::string& path, const Context&) {
        if (d.waveform == Waveform::kNone) return;
        if (d.rate_hz <= 0)
          fail(origin_of(node, "rate"), join(path, "rate"),
               "a driven region (waveform other than none) needs a rate > 0, e.g. \"72 bpm\"");
        if (d.waveform == Waveform::kFourier && d.harmonics.empty())
          fail(origin_of(node, "harmonics"), join(path, "harmonics"), "waveform fourier needs at least one harmonic");
        if (d.waveform == Waveform::kSamples && d.samples.empty())
          fail(origin_of(node, "samples"), join(path, "samples"), "waveform samples needs a list of 2..1024 samples");
        // phi = 1/2 + sum a_k cos(...) stays in [0, 1] only if the amplitudes sum to <= 1/2.
        double sum = 0;
        for (const Harmonic& h : d.harmonics) sum += h.amplitude;
        if (sum > 0.5 + 1e-12)
          fail(origin_of(node, "harmonics"), join(path, "harmonics"),
               "harmonic amplitudes sum to " + format_number(sum) + "; at most 0.5 keeps phi within [0, 1]");
      });
}

/// A list of {time, position} keys with increasing times.
ValueSpec<std::vector<PathKey>> path_keys(std::string position_doc) {
  auto key = map<PathKey>({
      field("time", quantity(Dimension::kTime, closed(0, 3600)), &PathKey::time_s, "When the point is here.")
          .required(),
      field("position", vec3(Dimension::kLength), &PathKey::position_m, std::move(position_doc)).required(),
  });
  return list(key, 1, 1024, "list of path keys")
      .also(
          [](const std::vector<PathKey>& keys) {
            for (std::size_t i = 1; i < keys.size(); ++i)
              if (keys[i].time_s <= keys[i - 1].time_s) return "times must increase (key " + std::to_string(i) + ")";
            return std::string();
          },
          "1..1024 keys, times increasing");
}

ValueSpec<ClipPlane> clip_spec() {
  return map<ClipPlane>(
      {
          field("point", vec3(Dimension::kLength), &ClipPlane::point_m, "A point on the cutting plane (world space)."),
          field("normal", direction(), &ClipPlane::normal,
                "Points to the side kept; the other side is cut away (normalised on reading).")
              .shown_default("required without `section`"),
          field("section",
                choice<Section>({{"four_chamber", Section::kFourChamber}, {"short_axis", Section::kShortAxis}}),
                &ClipPlane::section,
                "A named plane of the anatomical heart instead of point and normal: `four_chamber` (through the long "
                "axis and both ventricles, the front half cut away) or `short_axis` (across the long axis mid-ventricle, "
                "the apical half cut away). A view with this clip and no camera position looks square at the cut.")
              .shown_default("none"),
          field("cut_color", color(), &ClipPlane::cut_color, "Flat colour of the inside seen through the cut (sRGB)."),
      },
      [](const Node& node, ClipPlane& c, const std::string& path, const Context&) {
        c.enabled = true;
        const bool has_section = node.find("section") != nullptr;
        const bool has_plane = node.find("normal") != nullptr || node.find("point") != nullptr;
        if (has_section == has_plane || (!has_section && node.find("normal") == nullptr))
          fail(node.origin, path,
               std::string("expected `section`, or `normal` (with `point`); got ") +
                   (has_section ? "both" : node.find("point") ? "a point without a normal" : "neither"));
        c.normal.normalize();
      });
}

namespace {

ValueSpec<Transform> transform_spec() {
  return map<Transform>({
      field("translate", vec3(Dimension::kLength), &Transform::translate_m, "Position of the organ."),
      field("rotate", vec3(Dimension::kAngle), &Transform::rotate_rad, "Euler angles, applied X, then Y, then Z."),
      field("scale", number(open_closed(0, 1000)), &Transform::scale, "Uniform scale, applied before rotation."),
  });
}

ValueSpec<Material> material_spec() {
  return map<Material>({
      field("color", color(), &Material::color, "Surface colour (sRGB)."),
      field("specular", number(closed(0, 1)), &Material::specular, "Strength of the highlight."),
      field("shininess", number(closed(1, 1000)), &Material::shininess,
            "Blinn-Phong exponent: larger is a tighter highlight."),
      field("opacity", number(closed(0, 1)), &Material::opacity,
            "1 opaque; below 1 the organ is see-through (order-independent transparency, "
            "docs/teaching-visuals.md)."),
  });
}

ValueSpec<Electrophysiology> electrophysiology_spec() {
  return map<Electrophysiology>(
      {
          field("block",
                choice<BundleBranchBlock>({{"none", BundleBranchBlock::kNone},
                                           {"left_bundle_branch", BundleBranchBlock::kLeft},
                                           {"right_bundle_branch", BundleBranchBlock::kRight}}),
                &Electrophysiology::block,
                "A bundle branch that does not conduct: its ventricle is reached late, through the septum's "
                "muscle (left or right bundle branch block)."),
      },
      [](const Node&, Electrophysiology& e, const std::string&, const Context&) { e.enabled = true; });
}

Field<Organ> electrophysiology_field() {
  return field("electrophysiology", electrophysiology_spec(), &Organ::electrophysiology,
               "The heart's own conduction system: the sinus node starts every beat, and each part of the "
               "muscle contracts when the excitation reaches it (docs/electrophysiology.md), which also "
               "makes a computed 12-lead ECG. Needs `procedural: anatomical_heart`; a driven region may "
               "not give a `delay`, and every driven region beats at one rate (the sinus rate).")
      .shown_default("none");
}

/// With a conduction system the sinus node times every beat: only the generated heart has
/// one, a region's own delay would contradict it, and all driven regions beat at its rate.
void check_electrophysiology(const Node& node, const Organ& o, const std::string& path) {
  if (o.mesh.procedural != "anatomical_heart")
    fail(origin_of(node, "electrophysiology"), path + ".electrophysiology",
         "a conduction system needs the generated myocardium: `mesh: {procedural: anatomical_heart}`");
  const Node* regions = node.find("regions");
  const Region* paced = nullptr;
  for (std::size_t i = 0; regions && i < o.regions.size(); ++i) {
    const Region& r = o.regions[i];
    if (r.drive.waveform == physics::Waveform::kNone) continue;
    const Node& item = regions->items[i];
    const std::string at = path + ".regions[" + std::to_string(i) + "].drive";
    const Node* drive = item.find("drive");
    if (drive && drive->find("delay"))
      fail(origin_of(*drive, "delay"), at + ".delay",
           "with `electrophysiology` the conduction system starts each part's beat when the excitation reaches "
           "it; remove the region's delay");
    if (paced && (r.drive.rate_hz != paced->drive.rate_hz || r.drive.rate_end_hz != paced->drive.rate_end_hz))
      fail(drive ? origin_of(*drive, "rate") : origin_of(item, "drive"), at + ".rate",
           "with `electrophysiology` every driven region beats at the sinus rate; region '" + r.name +
               "' differs from '" + paced->name + "'");
    if (!paced) paced = &r;
  }
}

}  // namespace

ValueSpec<Organ> organ_spec() {
  return map<Organ>(
      {
          field("name", name_text(), &Organ::name, "Unique name; -D paths may use it (organs.heart.body.mass).")
              .required(),
          field("mesh", mesh_spec(), &Organ::mesh,
                "Where the surface comes from: exactly one of `file` or `procedural`.")
              .required(),
          field("transform", transform_spec(), &Organ::transform,
                "Placement in the world, applied after units and centring."),
          field("material", material_spec(), &Organ::material, "How the surface looks."),
          field("color_by",
                choice<ColorBy>({{"material", ColorBy::kMaterial},
                                 {"region", ColorBy::kRegion},
                                 {"strain", ColorBy::kStrain},
                                 {"activation", ColorBy::kActivation}}),
                &Organ::color_by,
                "What the surface colour shows: `material` (region colours where set), `region` (every region a "
                "colour: its own or a palette's), `strain` (mean (L - L0) / L0 of each vertex's edges, blue shortened, "
                "red stretched), `activation` (the region's drive phi(t), dark to yellow)."),
          field<Organ, Eigen::Vector2d>(
              "color_range", value_pair(),
              [](Organ& o) -> Eigen::Vector2d& {
                o.has_color_range = true;
                return o.color_range;
              },
              "`strain`, `activation`: the values at the two ends of the colour map.")
              .shown_default("strain [-0.15, 0.15]; activation [0, 1]"),
          field("clip", clip_spec(), &Organ::clip, "Cuts the organ open along a plane.").shown_default("none"),
          field("body", body_spec(), &Organ::body, "The soft body's physical parameters."),
          field("blood", blood_spec(), &Organ::blood,
                "The blood in an anatomical heart's ventricles: while both of a ventricle's valves are "
                "shut it keeps the cavity's volume, and its pressure opens them (Wiggers' four phases; "
                "docs/anatomy.md, \"Blood\"). Needs the generated myocardium and solver.method: projective.")
              .shown_default("none"),
          electrophysiology_field(),
          field("regions", list(region_spec(), 0, 256, "list of regions"), &Organ::regions,
                "Parts with their own rhythm and stiffness, applied in order."),
          field("collider", boolean(), &Organ::collider,
                "A static collider (a rib cage): drawn and touched by the other organs under `contact`, never "
                "simulated."),
          field("target", target_spec(), &Organ::target,
                "Motion for `systole tune` to fit the regions' drives to (docs/training.md).")
              .shown_default("none"),
      },
      [](const Node& node, Organ& o, const std::string& path, const Context&) {
        o.origin = node.origin;
        check_target_names(node, o, path);
        if (o.electrophysiology.enabled) check_electrophysiology(node, o, path);
        if (!o.has_color_range)
          o.color_range = o.color_by == ColorBy::kActivation ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(-0.15, 0.15);
        for (std::size_t i = 0; i < o.regions.size(); ++i)
          for (std::size_t j = 0; j < i; ++j)
            if (o.regions[i].name == o.regions[j].name)
              fail(origin_of(node.find("regions")->items[i], "name"), path + ".regions[" + std::to_string(i) + "].name",
                   "duplicate region name '" + o.regions[i].name + "' (also regions[" + std::to_string(j) + "])");
      });
}

}  // namespace systole::scene::schema
