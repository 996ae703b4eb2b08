#include "mesh/organ.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/error.h"
#include "mesh/import.h"
#include "mesh/procedural.h"
#include "scene/tree.h"

namespace systole::mesh {
namespace {

std::string written_at(const scene::Origin& origin) {
  if (origin.file.empty()) return "";
  std::string text = origin.file;
  // Appends one piece at a time (GCC 12 warns falsely on "literal" + std::string).
  if (origin.line > 0) text.append(":").append(std::to_string(origin.line));
  if (origin.column > 0) text.append(":").append(std::to_string(origin.column));
  return text.append(": ");
}

/// A part's name as validate lists it and a scene writes it (quoted when YAML needs it).
std::string shown(const std::string& part) { return scene::yaml_scalar(part); }

/// The parts nearest `name` (by edit distance to the whole name or to its last segment,
/// so "left_atrum" finds "heart/left_atrium"), at most 8: an atlas has thousands.
std::string nearest_parts(const OrganMesh& mesh, const std::string& name) {
  const std::vector<std::string>& names = mesh.part_names;
  if (names.empty()) return "the mesh has no named parts";
  std::vector<std::pair<std::size_t, std::size_t>> ranked;  // (distance, part)
  for (std::size_t p = 0; p < names.size(); ++p) {
    const std::size_t slash = names[p].rfind('/');
    std::size_t d = scene::edit_distance(name, names[p]);
    if (slash != std::string::npos) d = std::min(d, scene::edit_distance(name, names[p].substr(slash + 1)));
    ranked.emplace_back(d, p);
  }
  constexpr std::size_t kShown = 8;
  const std::size_t shown_count = std::min(kShown, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(shown_count), ranked.end());
  std::string text = ranked.size() > shown_count ? "nearest of its " + std::to_string(names.size()) + " parts: "
                                                 : "its parts, nearest first: ";
  for (std::size_t i = 0; i < shown_count; ++i) text += (i ? ", " : "") + shown(names[ranked[i].second]);
  if (ranked.size() > shown_count) text += " (`systole validate` lists them all once no region names a missing part)";
  return text;
}

/// The one part a region's part selector names (parts_named's rule), or an error naming the
/// region and the key: unknown (with the nearest names), ambiguous, or without a triangle.
int resolve_part(const OrganMesh& mesh, const scene::Region& region, const scene::Selector& selector, bool by_region_name) {
  const std::string key = written_at(selector.origin) + "region '" + region.name + "'" +
                          (by_region_name ? " (no select: the part named like the region)" : ": select.part");
  const std::vector<int> parts = mesh.parts_named(selector.part);
  if (parts.empty()) {
    throw Error(ExitCode::kDataError,
                key + ": the mesh has no part '" + selector.part + "'; " + nearest_parts(mesh, selector.part));
  }
  if (parts.size() > 1) {
    std::string names;
    for (const int p : parts) names += (names.empty() ? "" : ", ") + shown(mesh.part_names[static_cast<std::size_t>(p)]);
    throw Error(ExitCode::kDataError, key + ": '" + selector.part + "' ends the names of " + std::to_string(parts.size()) +
                                          " parts (" + names + "): write the whole name, as `systole validate` lists it");
  }
  const std::vector<char> in_part = mesh.part_mask(parts.front());
  if (std::find(in_part.begin(), in_part.end(), 1) == in_part.end()) {
    throw Error(ExitCode::kDataError, key + ": the mesh's part '" + mesh.part_names[static_cast<std::size_t>(parts.front())] +
                                          "' has no triangle (only points or lines, which are not read): select another part");
  }
  return parts.front();
}

// Whether a vertex at `p` is selected; `in_part` says whether it belongs to a kPart
// selector's part (resolved once by the caller).
bool selects(const scene::Selector& selector, bool in_part, const Eigen::Vector3d& p) {
  switch (selector.kind) {
    case scene::SelectorKind::kAll:
      return true;
    case scene::SelectorKind::kPart:
      return in_part;
    case scene::SelectorKind::kSphere:
      return (p - selector.center).squaredNorm() <= selector.radius_m * selector.radius_m;
    case scene::SelectorKind::kBox:
      return (p.array() >= selector.min.array()).all() && (p.array() <= selector.max.array()).all();
    case scene::SelectorKind::kHalfSpace:
      return (p - selector.point).dot(selector.normal) >= 0;
  }
  return false;
}

// Units, centring, then the transform: x' = T + Rz Ry Rx (s x); the anatomy's points alike.
void place(OrganMesh& mesh, const scene::MeshSource& source, const scene::Transform& transform) {
  const std::vector<Eigen::Vector3d>& positions = mesh.surface.positions;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  if (source.center && !positions.empty()) {
    Eigen::Vector3d lo = positions.front(), hi = positions.front();
    for (const Eigen::Vector3d& p : positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    centre = 0.5 * (lo + hi) * source.unit_m;
  }
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(transform.rotate_rad.z(), Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(transform.rotate_rad.y(), Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(transform.rotate_rad.x(), Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  auto move = [&](Eigen::Vector3d& p) { p = transform.translate_m + rotation * (transform.scale * (p * source.unit_m - centre)); };
  for (Eigen::Vector3d& p : mesh.surface.positions) move(p);
  for (Eigen::Vector3d& p : mesh.anatomy.myocardium.nodes) move(p);
  mesh.anatomy.body_axes = rotation * mesh.anatomy.body_axes;
  for (Valve& valve : mesh.anatomy.valves) {
    for (Eigen::Vector3d& p : valve.open_positions) move(p);
  }
}

// The region of every myocardium node: the regions' selectors applied to the nodes (by
// part, or by place), a later region taking a node from an earlier one. A region that
// selects no node (a valve's colour) is no error: it acts on the surface only.
std::vector<int> node_regions(const OrganMesh& mesh, const std::vector<scene::Region>& regions) {
  const Myocardium& myo = mesh.anatomy.myocardium;
  std::vector<int> node_region(myo.nodes.size(), -1);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    std::vector<scene::Selector> select = regions[r].select;
    if (select.empty()) {
      scene::Selector by_name;
      by_name.kind = scene::SelectorKind::kPart;
      by_name.part = regions[r].name;
      select.push_back(by_name);
    }
    for (const scene::Selector& selector : select) {
      std::vector<char> in_part(myo.nodes.size(), 0);
      if (selector.kind == scene::SelectorKind::kPart) {
        // chosen_by, run first, has refused a part that is not exactly one.
        const std::vector<int> parts = mesh.parts_named(selector.part);
        const int part = parts.size() == 1 ? parts.front() : -1;
        for (std::size_t n = 0; n < myo.nodes.size(); ++n) in_part[n] = myo.node_part[n] == part;
        for (const auto& [n, p] : myo.node_also_in) in_part[n] |= p == part;
      }
      for (std::size_t n = 0; n < myo.nodes.size(); ++n) {
        if (selects(selector, in_part[n], myo.nodes[n])) node_region[n] = static_cast<int>(r);
      }
    }
  }
  return node_region;
}

/// "17.3 cm", "3.46e+30 m": a length as a person reads it.
std::string length_text(double metres) {
  char text[48];
  if (metres >= 0.01 && metres < 1) {
    std::snprintf(text, sizeof text, "%.3g cm", metres * 100);
  } else if (metres >= 0.001 && metres < 0.01) {
    std::snprintf(text, sizeof text, "%.3g mm", metres * 1000);
  } else {
    std::snprintf(text, sizeof text, "%.3g m", metres);
  }
  return text;
}

// An organ is 5 mm to 2 m across. A mesh file outside that is a units mistake (a glTF is in
// metres by its specification; OBJ and STL exports are often in mm or cm), and would give
// an empty frame or a body the solver cannot hold (springs 1e-30 m long).
constexpr double kSmallestOrgan_m = 0.005, kLargestOrgan_m = 2.0;

void check_organ_size(const OrganMesh& mesh, const scene::Organ& organ, const std::string& label) {
  const auto& positions = mesh.surface.positions;
  Eigen::Vector3d lo = positions.front(), hi = positions.front();
  for (const Eigen::Vector3d& p : positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double across_m = (hi - lo).norm();
  if (across_m >= kSmallestOrgan_m && across_m <= kLargestOrgan_m) return;
  const double file_across = across_m / (organ.mesh.unit_m * organ.transform.scale);
  // The unit that makes it most like an organ (about 15 cm: log-distance), if any fits.
  std::string fit;
  double best = 1e300;
  for (const auto& [name, unit_m] : {std::pair{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}) {
    const double across = file_across * unit_m * organ.transform.scale;
    if (across < kSmallestOrgan_m || across > kLargestOrgan_m) continue;
    if (const double d = std::abs(std::log(across / 0.15)); d < best) {
      best = d;
      fit = std::string("write `units: ") + name + "` (then it is " + length_text(across) + " across)";
    }
  }
  if (fit.empty()) fit = "no unit (m, cm, mm) makes it organ-sized: check the file's scale, or set transform.scale";
  throw Error(ExitCode::kDataError, label + ": the mesh is " + length_text(across_m) +
                                        " across, but an organ is 5 mm to 2 m across, so its units are wrong; " + fit);
}

// The vertices one region's selectors choose (any of them); a part that is missing,
// ambiguous or without a triangle fails with the region's name.
std::vector<char> chosen_by(const OrganMesh& mesh, const scene::Region& region) {
  const std::vector<Eigen::Vector3d>& positions = mesh.surface.positions;
  // An empty selection means the part named like the region.
  std::vector<scene::Selector> select = region.select;
  if (select.empty()) {
    scene::Selector by_name;
    by_name.kind = scene::SelectorKind::kPart;
    by_name.part = region.name;
    by_name.origin = region.origin;
    select.push_back(by_name);
  }
  std::vector<char> chosen(positions.size(), 0);
  for (const scene::Selector& selector : select) {
    std::vector<char> in_part;
    if (selector.kind == scene::SelectorKind::kPart) {
      in_part = mesh.part_mask(resolve_part(mesh, region, selector, region.select.empty()));
    }
    for (size_t v = 0; v < positions.size(); ++v) {
      chosen[v] |= selects(selector, !in_part.empty() && in_part[v], positions[v]);
    }
  }
  return chosen;
}

// A vertex belongs to the last region that selects it, so a later region can take every
// vertex of an earlier one: that region, and its drive, would silently do nothing.
void check_every_region_keeps(const std::vector<int>& vertex_region, const std::vector<scene::Region>& regions) {
  std::vector<int> kept(regions.size(), 0);
  for (const int r : vertex_region) {
    if (r >= 0) ++kept[static_cast<size_t>(r)];
  }
  for (size_t r = 0; r < regions.size(); ++r) {
    if (kept[r] > 0) continue;
    std::string taker;
    for (size_t later = r + 1; later < regions.size(); ++later) {
      if (kept[later] > 0) taker += (taker.empty() ? "'" : ", '") + regions[later].name + "'";
    }
    throw Error(ExitCode::kDataError,
                written_at(regions[r].origin) + "region '" + regions[r].name + "' keeps no vertex: every vertex it selects is " +
                    "also selected by a later region (" + taker + "), and a vertex belongs to the last region that " +
                    "selects it; narrow the later region's selectors, or list '" + regions[r].name + "' after it");
  }
}

}  // namespace

std::vector<int> assign_regions(const OrganMesh& mesh, const std::vector<scene::Region>& regions) {
  const std::vector<Eigen::Vector3d>& positions = mesh.surface.positions;
  std::vector<int> vertex_region(positions.size(), -1);
  for (size_t r = 0; r < regions.size(); ++r) {
    const scene::Region& region = regions[r];
    const std::vector<char> chosen = chosen_by(mesh, region);
    int count = 0;
    for (size_t v = 0; v < positions.size(); ++v) {
      if (chosen[v]) vertex_region[v] = static_cast<int>(r), ++count;
    }
    if (count == 0) {
      throw Error(ExitCode::kDataError, written_at(region.origin) + "region '" + region.name +
                                            "' selects no vertex of the organ (selectors act on world positions, in metres)");
    }
  }
  check_every_region_keeps(vertex_region, regions);
  return vertex_region;
}

OrganGeometry build_organ_geometry(const scene::Organ& organ) {
  const std::string label = written_at(organ.origin) + "organ '" + organ.name + "'";
  OrganGeometry geometry;
  if (!organ.mesh.file.empty()) {
    geometry.mesh = import_mesh(organ.mesh.file);
  } else if (!organ.mesh.procedural.empty()) {
    geometry.mesh = generate_organ(organ.mesh.procedural, organ.mesh.detail);
  } else {
    throw Error(ExitCode::kDataError, label + ": no mesh (give mesh.file or mesh.procedural)");
  }
  if (geometry.mesh.surface.triangles.empty()) {
    throw Error(ExitCode::kDataError, label + ": the surface has no triangles");
  }
  place(geometry.mesh, organ.mesh, organ.transform);
  if (!organ.mesh.file.empty()) {
    // Units given by a -D are the likely cause of a wrong size: the message names that -D.
    const bool units_overridden = organ.mesh.units_origin.file.starts_with("-D");
    check_organ_size(geometry.mesh, organ, units_overridden ? written_at(organ.mesh.units_origin) + "organ '" + organ.name + "'" : label);
  }

  geometry.report = inspect(geometry.mesh.surface);
  // A closed surface that faces inwards is turned outwards: normals and volume need it.
  if (geometry.report.encloses_volume() && geometry.report.volume_m3 < 0) {
    for (Eigen::Vector3i& t : geometry.mesh.surface.triangles) std::swap(t[1], t[2]);
    geometry.report = inspect(geometry.mesh.surface);
    geometry.report.notes.push_back("inside out: the closed surface had negative volume; all triangles were flipped to face outwards");
  }
  if (geometry.mesh.dropped_triangles > 0) {
    geometry.report.notes.push_back(
        "dropped triangles: " + std::to_string(geometry.mesh.dropped_triangles) +
        " of the file's had a repeated corner (in the file, or after welding vertices closer than 1e-6 of the mesh's "
        "size) and are neither simulated nor drawn; if the surface shows holes there, fix the mesh in a modeller");
  }
  try {
    geometry.vertex_region = assign_regions(geometry.mesh, organ.regions);
    geometry.node_region = node_regions(geometry.mesh, organ.regions);
  } catch (const Error& error) {
    throw Error(error.code(), std::string(error.what()) + " [in " + label + "]");
  }
  return geometry;
}

}  // namespace systole::mesh
