// The thorax's walls, for scenes where organs touch (docs/contact.md): the diaphragm, a
// muscular dome closing the chest from below, and the chest wall, a band of ribs around the
// lungs. Both are thin closed solids built directly on a polar or cylindrical grid (they
// are not star-shaped, so not through the implicit mesher): a top and a bottom (or outer
// and inner) sheet joined at their rims, outward counter-clockwise.
//
// Frame: +Y towards the head, +Z anterior (the viewer), +X the patient's left.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/procedural/organs.h"

namespace systole::mesh::procedural {
namespace {

using Vec = Eigen::Vector3d;

/// Adds the quad (a, b, c, d) as two triangles (a, b, d), (a, d, c): outward when b - a runs
/// along the sheet and c - a across it with (b - a) x (c - a) pointing out.
void quad(std::vector<Eigen::Vector3i>& t, int a, int b, int c, int d) {
  t.emplace_back(a, b, d);
  t.emplace_back(a, d, c);
}

// --- Diaphragm ---------------------------------------------------------------------------

enum DiaphragmPart : int { kCentralTendon, kRightDome, kLeftDome, kMuscularRim, kCostalMargin, kDiaphragmParts };
const char* const kDiaphragmNames[kDiaphragmParts] = {"central_tendon", "right_dome", "left_dome", "muscular_rim",
                                                      "costal_margin"};

constexpr double kDomeRadiusX = 0.15;     ///< Half-width of the footprint. unit: m
constexpr double kDomeRadiusZ = 0.115;    ///< Half-depth of the footprint. unit: m
constexpr double kDomeHeight = 0.05;      ///< Rise of the dome above its rim. unit: m
constexpr double kDomeThickness = 0.008;  ///< unit: m
/// The dome's crest lies this far in front of the footprint's centre: the central tendon,
/// where the heart rests, is anterior, so the heart sits on the flat of the dome. unit: m
constexpr double kDomeCrestZ = 0.04;

/// Normalized radius within which the dome's top is flat: the central tendon, where the
/// heart rests (a paraboloid's crest would meet the heart's rounded wall at a point and
/// dent it; a flat tendon spreads the load over square centimetres). unit: 1
constexpr double kTendonFlat = 0.4;

/// The drop of the upper sheet below the crest, as a fraction of kDomeHeight: rho^2 (a
/// paraboloid) outside kTendonFlat; inside, a quartic with the same value and slope at
/// kTendonFlat and none at the centre (within rho 0.3 it stays within 2.5 % of the dome's
/// height, 1.3 mm, of flat). unit: 1
double dome_drop(double rho) {
  constexpr double r2 = kTendonFlat * kTendonFlat;
  return rho >= kTendonFlat ? rho * rho : 0.5 * (rho * rho * rho * rho / r2 + r2);
}

/// The upper sheet's height at normalized radius rho and x: a dome with a flat top, the
/// right side (-X, over the liver) higher than the left. unit: m
double dome_height(double rho, double x) { return kDomeHeight * (1.0 - dome_drop(rho)) * (1.0 - 0.15 * x / kDomeRadiusX); }

int diaphragm_part(double rho, double x) {
  if (rho >= 0.95) return kCostalMargin;
  if (rho >= 0.85) return kMuscularRim;
  if (rho < 0.3) return kCentralTendon;
  return x < 0 ? kRightDome : kLeftDome;
}

}  // namespace

OrganMesh diaphragm(int detail) {
  // About target_triangles: 4 S R triangles on the two sheets, S = 3 R sectors.
  const int rings = std::max(4, static_cast<int>(std::lround(std::sqrt(target_triangles(detail) / 12.0))));
  const int sectors = 3 * rings;
  OrganMesh m;
  m.part_names.assign(kDiaphragmNames, kDiaphragmNames + kDiaphragmParts);
  auto& p = m.surface.positions;
  const int half = 1 + rings * sectors;  // Vertices of one sheet.
  for (int sheet = 0; sheet < 2; ++sheet) {
    const double drop = sheet == 0 ? 0.0 : kDomeThickness;
    p.emplace_back(0.0, dome_height(0, 0) - drop, kDomeCrestZ);
    m.vertex_part.push_back(kCentralTendon);
    for (int j = 1; j <= rings; ++j) {
      const double rho = double(j) / rings;
      for (int k = 0; k < sectors; ++k) {
        const double theta = 2.0 * std::numbers::pi * k / sectors;
        const double x = rho * kDomeRadiusX * std::cos(theta);
        const double z = rho * kDomeRadiusZ * std::sin(theta) + kDomeCrestZ * (1.0 - rho * rho);
        p.emplace_back(x, dome_height(rho, x) - drop, z);
        m.vertex_part.push_back(diaphragm_part(rho, x));
      }
    }
  }
  const auto at = [&](int sheet, int j, int k) { return sheet * half + (j == 0 ? 0 : 1 + (j - 1) * sectors + (k % sectors)); };
  auto& t = m.surface.triangles;
  for (int k = 0; k < sectors; ++k) {
    t.emplace_back(at(0, 0, 0), at(0, 1, k + 1), at(0, 1, k));  // Upper sheet, facing up.
    t.emplace_back(at(1, 0, 0), at(1, 1, k), at(1, 1, k + 1));  // Lower sheet, facing down.
    for (int j = 1; j < rings; ++j) {
      quad(t, at(0, j, k), at(0, j, k + 1), at(0, j + 1, k), at(0, j + 1, k + 1));
      quad(t, at(1, j, k + 1), at(1, j, k), at(1, j + 1, k + 1), at(1, j + 1, k));
    }
    // The rim joins the sheets, facing out.
    t.emplace_back(at(0, rings, k), at(0, rings, k + 1), at(1, rings, k + 1));
    t.emplace_back(at(0, rings, k), at(1, rings, k + 1), at(1, rings, k));
  }
  return m;
}

namespace {

// --- Chest wall --------------------------------------------------------------------------

enum WallPart : int { kRibs, kIntercostal, kSternum, kSpine, kWallParts };
const char* const kWallNames[kWallParts] = {"ribs", "intercostal", "sternum", "spine"};

constexpr double kWallBottom = -0.20, kWallTop = 0.13;  ///< unit: m
constexpr double kWallRadiusX = 0.158;   ///< Inner half-width at its widest. unit: m
constexpr double kWallRadiusZ = 0.13;    ///< Inner half-depth at its widest. unit: m
constexpr double kWallThickness = 0.012;  ///< unit: m
constexpr double kRibPitch = 0.034;       ///< Rib to rib, along the wall. unit: m

/// The inner section's shrink with height: a barrel that narrows towards the apex of the
/// lungs. unit: 1
double wall_taper(double y) {
  const double above = std::max(0.0, (y - 0.0) / (kWallTop - 0.0));
  return 1.0 - 0.3 * above * above;
}

int wall_part(const Vec& x) {
  if (std::abs(x.x()) < 0.022) return x.z() > 0 ? kSternum : kSpine;
  const double phase = (x.y() - kWallBottom) / kRibPitch;
  return phase - std::floor(phase) < 0.45 ? kRibs : kIntercostal;
}

}  // namespace

OrganMesh chest_wall(int detail) {
  const int sectors = 48 + 16 * detail, rows = 14 * detail;
  OrganMesh m;
  m.part_names.assign(kWallNames, kWallNames + kWallParts);
  auto& p = m.surface.positions;
  const int sheet_size = rows * sectors;
  for (int sheet = 0; sheet < 2; ++sheet) {  // 0: outer, 1: inner.
    const double grow = sheet == 0 ? kWallThickness : 0.0;
    for (int i = 0; i < rows; ++i) {
      const double y = kWallBottom + (kWallTop - kWallBottom) * i / (rows - 1);
      const double taper = wall_taper(y);
      for (int k = 0; k < sectors; ++k) {
        const double theta = 2.0 * std::numbers::pi * k / sectors;
        const Vec x((kWallRadiusX * taper + grow) * std::cos(theta), y, (kWallRadiusZ * taper + grow) * std::sin(theta));
        p.push_back(x);
        m.vertex_part.push_back(wall_part(x));
      }
    }
  }
  const auto at = [&](int sheet, int i, int k) { return sheet * sheet_size + i * sectors + (k % sectors); };
  auto& t = m.surface.triangles;
  for (int k = 0; k < sectors; ++k) {
    for (int i = 0; i + 1 < rows; ++i) {
      quad(t, at(0, i, k), at(0, i + 1, k), at(0, i, k + 1), at(0, i + 1, k + 1));  // Outer, facing out.
      quad(t, at(1, i, k), at(1, i, k + 1), at(1, i + 1, k), at(1, i + 1, k + 1));  // Inner, facing the axis.
    }
    const int top = rows - 1;
    quad(t, at(1, top, k), at(1, top, k + 1), at(0, top, k), at(0, top, k + 1));  // Upper rim, facing up.
    quad(t, at(1, 0, k + 1), at(1, 0, k), at(0, 0, k + 1), at(0, 0, k));          // Lower rim, facing down.
  }
  return m;
}

}  // namespace systole::mesh::procedural
