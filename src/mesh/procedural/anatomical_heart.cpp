// The procedural anatomical heart: four chambers with muscular walls, the septa, the atrial
// appendages, four valves, hollow great vessels and the coronary arteries, with a volumetric
// myocardium whose fibres run in helices (mesh/procedural/walls.h builds the walls).
//
// Frame: +Y towards the head, +Z anterior (the viewer), +X the patient's left. The long axis
// runs from the base down, forward and to the left to the apex. The left heart (ventricle
// below, atrium above, the mitral annulus between) is one wall of revolution about that
// axis; the right heart another beside it, in front and to the right, whose wall gives way
// where it meets the left's: there the two walls are glued into the interventricular and
// interatrial septa, and the right ventricle wraps the left as a crescent.
//
// Dimensions (end-diastole, the body's rest): left ventricle about 8 cm long inside and
// 5 cm across, wall 10 mm (apex 7 mm); right ventricle wall 3.5-4 mm; atrial walls 2.5 mm;
// mitral annulus 3.2 cm across, tricuspid 3.6 cm; aorta 2.6 cm, pulmonary trunk 2.4 cm.
// After Lang et al. 2015, "Recommendations for cardiac chamber quantification by
// echocardiography in adults" (J Am Soc Echocardiogr 28:1-39) for chamber sizes and wall
// thicknesses, and Gray's Anatomy (41st ed., ch. 57) for the chambers' places.
// Fibres: helix angle +60 deg at the lining to -60 deg outside in the ventricles (Streeter
// et al. 1969, "Fiber orientation in the canine left ventricle during diastole and systole",
// Circ Res 24:339-347), assigned by rule as in Bayer et al. 2012 (Ann Biomed Eng 40:2243);
// circumferential in the atria.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "mesh/procedural/organs.h"
#include "mesh/procedural/walls.h"

namespace systole::mesh::procedural {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double mm = 0.001;

const std::vector<std::string> kPartNames = {
    "left_ventricle", "right_ventricle", "left_atrium", "right_atrium", "apex", "aorta", "pulmonary_trunk",
    "superior_vena_cava", "inferior_vena_cava", "pulmonary_veins", "left_ventricle_cavity", "right_ventricle_cavity",
    "left_atrium_cavity", "right_atrium_cavity", "interventricular_septum", "interatrial_septum",
    "left_atrial_appendage", "right_atrial_appendage", "mitral_valve", "tricuspid_valve", "aortic_valve",
    "pulmonary_valve", "coronary_arteries"};

// The lining's meridians, apex to the top of the atrium: height towards the apex from the
// annulus, radius, wall thickness (mm). Key 7 is the annulus (the atrioventricular groove).
constexpr int kAnnulusKey = 7;
const std::vector<double> kLeftHeight = {78, 72, 60, 45, 28, 12, 3, 0, -6, -16, -28, -38, -42};
const std::vector<double> kLeftRadius = {0, 12, 19.5, 24, 25.5, 24.5, 20, 16, 21, 23, 21, 12, 0};
const std::vector<double> kLeftThickness = {7, 8, 10, 10.5, 10.5, 10, 8, 4, 2.5, 2.5, 2.5, 2.5, 2.5};
const std::vector<double> kRightHeight = {66, 60, 48, 34, 20, 8, 2, 0, -6, -16, -28, -37, -41};
const std::vector<double> kRightRadius = {0, 14.5, 24.5, 30, 31, 29, 24, 19, 24, 27, 25, 14, 0};
const std::vector<double> kRightThickness = {4, 4, 4, 3.5, 3.5, 3.5, 3.5, 3, 2.5, 2.5, 2.5, 2.5, 2.5};
constexpr double kAnnulusAlong = double(kAnnulusKey) / 12;
constexpr double kApexAlong = 2.0 / 12;
constexpr double kRightOffset = 42 * mm;     // Between the two walls' axes.
constexpr double kRightLower = 6 * mm;       // The tricuspid annulus lies lower than the mitral.
constexpr double kSeptumOverlap = 1.5 * mm;  // The right wall reaches into the left's.
constexpr double kRightLean = 10 * mm;       // The right ventricle's apex towards the left's axis.
constexpr double kRightWiden = 1.4;          // Its radii below the annulus, against the meridian's.
constexpr double kWidenOver = 0.16;          // The share of the meridian it widens over, from just above the annulus.
constexpr double kGrooveRise = 60 * mm;      // Per radian: how steeply the free wall rises out of the grooves.
constexpr double kGrooveSoft = 6 * mm;       // How round the free wall turns into a groove.

std::vector<double> in_metres(const std::vector<double>& millimetres) {
  std::vector<double> m;
  for (double v : millimetres) m.push_back(v * mm);
  return m;
}

double angle_between(double a, double b) { return std::abs(std::remainder(a - b, 2 * kPi)); }

// The smaller of a and b, rounded over `soft` where they are close (a log-sum-exp). unit: as a, b
double smooth_min(double a, double b, double soft) {
  const double low = std::min(a, b);
  return low - soft * std::log1p(std::exp(-std::abs(a - b) / soft));
}

// The angle around a wall's axis at which its radial direction is nearest to `direction`.
double around_towards(const WallShape& w, const Vec& direction) {
  return std::atan2(direction.dot(w.e2), direction.dot(w.e1));
}

struct Layout {
  Vec axis = Vec(0.43, -0.82, 0.37).normalized();  // Base to apex.
  Vec anterior, left, to_right_heart;
  Vec left_origin = Vec(0.004, 0.020, -0.010);  // Centre of the mitral annulus. unit: m
  Layout() {
    anterior = (Vec::UnitZ() - axis * axis.dot(Vec::UnitZ())).normalized();
    left = anterior.cross(axis);
    to_right_heart = (-0.55 * left + 0.83 * anterior).normalized();
  }
};

WallShape wall_of_revolution(const Vec& origin, const Vec& axis, const Vec& e1, int detail) {
  WallShape w;
  w.origin = origin;
  w.axis = axis;
  w.e1 = e1;
  w.e2 = axis.cross(e1);
  w.columns = detail <= 2 ? 16 : 20;
  w.rows_per_key = detail >= 5 ? 2 : 1;
  w.layers = 3;
  w.draw_columns = 16 + 8 * detail;
  w.draw_rows_per_key = 1 + detail / 2;
  return w;
}

// Ventricles: +60 deg at the lining to -60 deg outside; atria: circumferential.
double helix(double across, double along) { return along < kAnnulusAlong ? (60.0 - 120.0 * across) * kPi / 180 : 0.0; }

// Cross-fibre shortening as a share of the fibre's: as much as the fibre's under the lining,
// a tenth of it outside (Costa et al. 1999, "Laminar fiber architecture and
// three-dimensional systolic mechanics in canine ventricular myocardium", Am J Physiol
// 276:H595; Rademakers et al. 1994): the lining thickens the wall and the outside, which
// shortens along its fibres alone, twists it.
double cross_fibre(double across, double) { return 1.0 - 0.9 * across; }

// Where the right wall meets the left, shared by its shape and its parts: its lean towards
// the left's apex, its meridian's heights, the contact with the left wall, its appendage.
struct RightMeetsLeft {
  const Wall* left;
  Vec e1, e2;
  std::vector<double> heights;  // unit: m
  double appendage_around;      // unit: rad

  // The ventricle leans towards the left's apex: its rings below the annulus move towards
  // the left wall's axis, most at its own apex, so its lower end runs into the left's apex
  // instead of rounding off beside it as a second ball. unit: m
  static double lean(double along) {
    return along >= kAnnulusAlong ? 0.0 : kRightLean * std::pow(1 - along / kAnnulusAlong, 2);
  }
  // A ray from the right wall's axis in the plane at `along`'s height, against the left
  // wall's outside there: how far along it the left axis lies, how far from it it passes. unit: m
  struct Ray {
    double left_radius, towards, passing;
  };
  Ray ray(double around, double along) const {
    const double offset = kRightOffset - lean(along);  // Between the two axes here.
    const double towards = offset * (std::cos(around) * e1 + std::sin(around) * e2).dot(e1);
    return {left->outside_radius_at(height_at(along) + kRightLower, 0), towards,
            std::sqrt(std::max(0.0, offset * offset - towards * towards))};
  }
  double height_at(double along) const {  // Linear is close enough to decide the contact.
    const double u = along * (heights.size() - 1);
    const int i = std::min(static_cast<int>(u), static_cast<int>(heights.size()) - 2);
    return heights[i] + (u - i) * (heights[i + 1] - heights[i]);
  }
  // Where a ray from the right wall's axis meets the left wall's outside, in the plane at
  // this height: the right wall stops there (overlapping a little), so the septum is one
  // wall and the right ventricle a crescent round the left. 0: no contact.
  double contact(double around, double along) const {
    const Ray r = ray(around, along);
    const double disc = r.left_radius * r.left_radius - r.passing * r.passing;
    if (r.left_radius <= 0 || r.towards <= 0 || disc < 0) return 0.0;
    return std::max(0.0, r.towards - std::sqrt(disc));
  }
  // How far the right wall may reach along the ray, against the ray's angle from the left
  // axis' direction: the contact while it rises no faster than kGrooveRise, then rising at
  // that rate, past the tangent ray and beside the left wall, so the free wall closes on the
  // left's in a groove. The contact alone rises ever faster towards the tangent ray and stops
  // there: a cliff (12 -> 20 mm in front, 12 -> 40 mm behind, half way down) that no ring of
  // vertices resolves, its wall with no thickness between lining and outside, the seam along
  // the interventricular grooves. 0: no limit.
  double reach(double around, double along) const {
    const Ray r = ray(around, along);
    const double offset = std::hypot(r.towards, r.passing);
    if (r.left_radius <= 0 || offset <= r.left_radius) return 0.0;
    // The contact at angle a from the left axis' direction, and its rise there. unit: m, m/rad
    auto meet = [&](double a) {
      return offset * std::cos(a) - std::sqrt(std::max(0.0, r.left_radius * r.left_radius - std::pow(offset * std::sin(a), 2)));
    };
    auto rise = [&](double a) {
      const double chord = std::sqrt(std::max(1e-18, r.left_radius * r.left_radius - std::pow(offset * std::sin(a), 2)));
      return -offset * std::sin(a) + offset * offset * std::sin(a) * std::cos(a) / chord;
    };
    const double tangent = std::asin(r.left_radius / offset);
    double lo = 0, hi = tangent;  // The rise grows from 0 straight ahead to no bound at the tangent.
    for (int i = 0; i < 50; ++i) (rise(0.5 * (lo + hi)) < kGrooveRise ? lo : hi) = 0.5 * (lo + hi);
    const double angle = std::atan2(r.passing, r.towards);
    if (angle <= lo) return std::max(0.0, meet(angle));
    return meet(lo) + kGrooveRise * (angle - lo);
  }
  double appendage(double around, double along) const {
    return std::exp(-std::pow(angle_between(around, appendage_around) / 0.4, 2) - std::pow((along - 0.70) / 0.07, 2));
  }
};

class Heart {
 public:
  explicit Heart(int detail) : builder_(kPartNames), detail_(detail) {}
  OrganMesh build();

 private:
  int part(const char* name) const { return builder_.part(name); }
  Wall make_left();
  Wall make_right(const Wall& left);
  std::function<double(double, double, double, double)> right_radius(const RightMeetsLeft& g, const Vec& origin) const;
  Wall make_vessel(const char* name, const Vec& root, const Vec& direction, double radius, double thickness,
                   double length);
  void glue_root(const Wall& vessel, const Wall& chamber);
  void add_valve(const Wall& wall, double along, int leaflets, const char* name, const char* chamber, bool inflow);
  void add_coronary(const Wall& wall, const std::vector<std::pair<double, double>>& path, double radius);
  void add_cavities_and_landmarks(const Wall& left, const Wall& right);

  HeartBuilder builder_;
  int detail_;
  Layout layout_;
};

Wall Heart::make_left() {
  WallShape w = wall_of_revolution(layout_.left_origin, layout_.axis, layout_.to_right_heart, detail_);
  w.height = in_metres(kLeftHeight);
  w.radius = in_metres(kLeftRadius);
  w.thickness = in_metres(kLeftThickness);
  w.helix_rad = helix;
  w.cross_fibre = cross_fibre;
  // The left atrial appendage: a lobe on the atrium's front left, beside the pulmonary trunk.
  const double appendage_around = around_towards(w, (layout_.anterior + 0.9 * layout_.left).normalized());
  auto appendage = [appendage_around](double around, double along) {
    return std::exp(-std::pow(angle_between(around, appendage_around) / 0.33, 2) - std::pow((along - 0.72) / 0.06, 2));
  };
  w.shape_radius = [appendage](double around, double along, double radius, double) {
    return radius + 8 * mm * appendage(around, along);
  };
  const int lv = part("left_ventricle"), la = part("left_atrium"), apex = part("apex");
  const int lv_cavity = part("left_ventricle_cavity"), la_cavity = part("left_atrium_cavity");
  const int ivs = part("interventricular_septum"), ias = part("interatrial_septum");
  const int laa = part("left_atrial_appendage");
  return Wall(builder_, w, [=](const WallPoint& p, bool drawn) {
    const bool ventricle = p.along <= kAnnulusAlong + 1e-9;
    std::vector<int> parts;
    if (drawn && p.across == 0) parts.push_back(ventricle ? lv_cavity : la_cavity);
    parts.push_back(ventricle ? (p.along < kApexAlong ? apex : lv) : la);
    if (ventricle && p.along >= kApexAlong && angle_between(p.around, 0) < 0.75) parts.push_back(ivs);
    if (!ventricle && angle_between(p.around, 0) < 0.6) parts.push_back(ias);
    if (!ventricle && appendage(p.around, p.along) > 0.3) parts.push_back(laa);
    return parts;
  });
}

Wall Heart::make_right(const Wall& left) {
  const Vec origin = layout_.left_origin + kRightOffset * layout_.to_right_heart + kRightLower * layout_.axis;
  WallShape w = wall_of_revolution(origin, layout_.axis, -layout_.to_right_heart, detail_);
  w.height = in_metres(kRightHeight);
  w.radius = in_metres(kRightRadius);
  w.thickness = in_metres(kRightThickness);
  w.helix_rad = helix;
  w.cross_fibre = cross_fibre;
  const Vec towards_left = layout_.to_right_heart;
  w.shift = [=](double along) -> Vec { return -RightMeetsLeft::lean(along) * towards_left; };
  const RightMeetsLeft g{&left, w.e1, w.e2, in_metres(kRightHeight),
                         around_towards(w, (layout_.anterior - 0.6 * layout_.left).normalized())};
  w.shape_radius = right_radius(g, origin);
  const int rv = part("right_ventricle"), ra = part("right_atrium");
  const int rv_cavity = part("right_ventricle_cavity"), ra_cavity = part("right_atrium_cavity");
  const int ivs = part("interventricular_septum"), ias = part("interatrial_septum");
  const int raa = part("right_atrial_appendage");
  const auto septal = [=](double around, double along, double radius_limit) {
    return g.contact(around, along) > 0 && g.contact(around, along) < radius_limit;
  };
  Wall right(builder_, w, [=](const WallPoint& p, bool drawn) {
    const bool ventricle = p.along <= kAnnulusAlong + 1e-9;
    std::vector<int> parts;
    if (drawn && p.across == 0) parts.push_back(ventricle ? rv_cavity : ra_cavity);
    parts.push_back(ventricle ? rv : ra);
    if (septal(p.around, p.along, 0.04)) parts.push_back(ventricle ? ivs : ias);
    if (!ventricle && g.appendage(p.around, p.along) > 0.3) parts.push_back(raa);
    return parts;
  });
  // Glue the septum: each outside node where the walls meet holds to the left wall's nearest.
  for (int n : right.outside_nodes()) {
    const Vec& x = builder_.node_position(n);
    for (int m : left.nodes_near(x, 6 * mm, 2, true)) builder_.glue(n, m);
  }
  return right;
}

// The ventricle's free wall lies behind two planes, its flat faces: the sternocostal face
// in front, turned towards the apex and the left so it recedes into the interventricular
// groove and the apex (one cone with the left ventricle from the front, not a second
// ball), and the diaphragmatic face below, rising to the right; they meet at the acute
// margin. The wall is wider than its meridian says to keep its cavity's volume.
std::function<double(double, double, double, double)> Heart::right_radius(const RightMeetsLeft& g,
                                                                          const Vec& origin) const {
  const Vec towards_left = layout_.to_right_heart;
  const Vec front = (layout_.anterior + 0.3 * layout_.axis + 1.0 * layout_.left).normalized();
  const double front_from_origin = front.dot(origin) + 24 * mm;
  const Vec below = Vec(-0.5, -1, 0).normalized();
  const double below_from_origin = below.dot(origin) + 44 * mm;
  const Vec axis = layout_.axis;
  return [=](double around, double along, double radius, double thickness) {
    // The ventricle only (the atrium keeps its size), blended in below the annulus: blended
    // over 0.08 of the meridian, the widening made a ledge under the tricuspid annulus whose
    // outside folded as the ventricle contracted, and the lining showed there. 1.4 (was 1.3)
    // keeps the cavity's 94 ml that the grooves now take from it.
    radius *= 1 + (kRightWiden - 1) * std::clamp((kAnnulusAlong + 0.04 - along) / kWidenOver, 0.0, 1.0);
    double r = radius + 9 * mm * g.appendage(around, along);
    if (along <= kAnnulusAlong + 0.05) {
      const Vec ray = std::cos(around) * g.e1 + std::sin(around) * g.e2;
      const Vec centre = origin + g.height_at(along) * axis - g.lean(along) * towards_left;
      constexpr double soft = 3 * mm;  // A smooth minimum: the faces meet the round wall without a crease.
      double limit = r;
      for (const auto& [n, d] : {std::pair{front, front_from_origin}, std::pair{below, below_from_origin}}) {
        const double towards = n.dot(ray);
        if (towards <= 1e-3) continue;
        const double most = (d - n.dot(centre)) / towards - thickness;  // The outside on the plane.
        limit = smooth_min(limit, most, soft);
      }
      r = std::max(limit, 0.25 * radius);
    }
    // Near its apex the leaning wall nearly touches the left's: it may thin to a slit there,
    // but never reach through the septum into the left cavity.
    if (const double reach = g.reach(around, along); reach > 0) {
      r = std::max(0.05 * radius, smooth_min(r, reach + kSeptumOverlap - thickness, kGrooveSoft));
    }
    return r;
  };
}

Wall Heart::make_vessel(const char* name, const Vec& root, const Vec& direction, double radius, double thickness,
                        double length) {
  WallShape w;
  w.tube = true;
  w.axis = -direction.normalized();  // Heights grow towards the heart; the tube runs away from it.
  w.origin = root;
  w.e1 = w.axis.unitOrthogonal();
  w.e2 = w.axis.cross(w.e1);
  w.height = {0, -length};
  w.radius = {radius, radius};
  w.thickness = {thickness, thickness};
  w.columns = 12;
  w.rows_per_key = 2;
  w.layers = 1;
  w.draw_columns = 24;
  w.draw_rows_per_key = 4;
  const int vessel = part(name);
  return Wall(builder_, w, [vessel](const WallPoint&, bool) { return std::vector<int>{vessel}; });
}

void Heart::glue_root(const Wall& vessel, const Wall& chamber) {
  for (int c = 0; c < vessel.shape().columns; ++c) {
    for (int n : vessel.nodes_near(vessel.point({2 * kPi * c / vessel.shape().columns, 0, 0.5}), 4 * mm, 2, false)) {
      for (int m : chamber.nodes_near(builder_.node_position(n), 14 * mm, 2, false)) builder_.glue(n, m);
    }
  }
}

// Leaflets (or cusps) spanning the lining at `along`: closed they meet in the middle, bowed
// back against the flow; open they lie along the wall downstream (into the ventricle for an
// inflow valve, up the vessel for an outflow one).
void Heart::add_valve(const Wall& wall, double along, int leaflets, const char* name, const char* chamber, bool inflow) {
  const int columns = 10, rows = 5, valve_part = part(name);
  Vec centre = Vec::Zero();
  for (int i = 0; i < 64; ++i) centre += wall.point({2 * kPi * i / 64, along, 0}) / 64;
  // Downstream: towards the apex for an inflow valve; along the vessel (away from the heart) for an outflow one.
  const Vec downstream = inflow ? wall.shape().axis : Vec(-wall.shape().axis);
  Valve valve;
  valve.name = name;
  valve.chamber = chamber;
  valve.opens_on_filling = inflow;
  const double gap = 0.05;
  for (int leaf = 0; leaf < leaflets; ++leaf) {
    const double from = 2 * kPi * leaf / leaflets + gap, to = 2 * kPi * (leaf + 1) / leaflets - gap;
    std::vector<int> grid;
    for (int r = 0; r < rows; ++r) {
      const double reach = 0.97 * r / (rows - 1);
      for (int c = 0; c <= columns; ++c) {
        const double around = from + (to - from) * c / columns;
        const Vec ring = wall.point({around, along, 0});
        const Vec inward = centre - ring;
        // Closed: towards the middle, bowed upstream; the free edge's middle reaches furthest.
        const double edge = std::sin(kPi * c / columns);
        const Vec closed = ring + reach * (0.75 + 0.25 * edge) * inward - 0.12 * inward.norm() * std::sin(kPi * reach) * downstream;
        const Vec open = ring + reach * 0.8 * inward.norm() * (std::cos(0.3) * downstream + std::sin(0.3) * inward.normalized());
        std::array<int, 8> nodes;
        std::array<double, 8> weights;
        wall.carriers({around, along, 0}, nodes, weights);
        grid.push_back(builder_.add_vertex(closed, {valve_part}, nodes, weights));
        valve.vertices.push_back(grid.back());
        valve.open_positions.push_back(open);
      }
    }
    for (int r = 0; r + 1 < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        const int a = grid[r * (columns + 1) + c], b = grid[r * (columns + 1) + c + 1];
        const int d = grid[(r + 1) * (columns + 1) + c], e = grid[(r + 1) * (columns + 1) + c + 1];
        builder_.add_triangle_facing(a, d, b, -downstream);
        builder_.add_triangle_facing(b, d, e, -downstream);
      }
    }
  }
  builder_.mesh().anatomy.valves.push_back(std::move(valve));
}

// A coronary artery: a thin tube lying on a wall's outside along a path of (around, along),
// tapering at both ends.
void Heart::add_coronary(const Wall& wall, const std::vector<std::pair<double, double>>& path, double radius) {
  const int samples = 8 * detail_ + 8, sides = 6, artery = part("coronary_arteries");
  std::vector<Vec> centre;
  std::vector<WallPoint> at;
  for (int i = 0; i <= samples; ++i) {
    const double u = double(i) / samples * (path.size() - 1);
    const int k = std::min(static_cast<int>(u), static_cast<int>(path.size()) - 2);
    const double f = u - k;
    const WallPoint p{path[k].first + f * (path[k + 1].first - path[k].first),
                      path[k].second + f * (path[k + 1].second - path[k].second), 1.0};
    Vec t, m, normal;
    wall.frame(p, t, m, normal);
    at.push_back(p);
    centre.push_back(wall.point(p) + 0.7 * radius * normal);
  }
  std::vector<int> ring_start;
  for (int i = 0; i <= samples; ++i) {
    const Vec tangent = (centre[std::min(i + 1, samples)] - centre[std::max(i - 1, 0)]).normalized();
    const Vec side = tangent.unitOrthogonal(), up = tangent.cross(side);
    const double taper = std::min({1.0, 4.0 * i / samples + 0.05, 4.0 * (samples - i) / samples + 0.05});
    std::array<int, 8> nodes;
    std::array<double, 8> weights;
    wall.carriers(at[i], nodes, weights);
    ring_start.push_back(static_cast<int>(builder_.mesh().surface.positions.size()));
    for (int s = 0; s < sides; ++s) {
      const double a = 2 * kPi * s / sides;
      builder_.add_vertex(centre[i] + taper * radius * (std::cos(a) * side + std::sin(a) * up), {artery}, nodes, weights);
    }
  }
  for (int i = 0; i < samples; ++i) {
    for (int s = 0; s < sides; ++s) {
      const int a = ring_start[i] + s, b = ring_start[i] + (s + 1) % sides;
      const int c = ring_start[i + 1] + s, d = ring_start[i + 1] + (s + 1) % sides;
      const Vec out = builder_.vertex_position(a) - centre[i];
      builder_.add_triangle_facing(a, b, c, out);
      builder_.add_triangle_facing(b, d, c, out);
    }
  }
}

void Heart::add_cavities_and_landmarks(const Wall& left, const Wall& right) {
  Anatomy& anatomy = builder_.mesh().anatomy;
  anatomy.myocardium.annulus_along = kAnnulusAlong;
  for (const Wall* wall : {&left, &right}) {
    const bool is_left = wall == &left;
    const int annulus = wall->draw_row_of_key(kAnnulusKey), last = wall->draw_rows() - 1;
    anatomy.cavities.push_back({is_left ? "left_ventricle" : "right_ventricle", wall->lining(0, annulus), {}});
    anatomy.cavities.push_back({is_left ? "left_atrium" : "right_atrium", wall->lining(annulus, last), {}});
  }
  for (Cavity& cavity : anatomy.cavities) find_rims(cavity);
  // Hidden by the walls' outside: the linings and the inflow valves' leaflets. Not the right
  // ventricle's: where its flattened wall closes on the left's at the top of the
  // interventricular groove, a sliver of its lining shows (a few pixels of a 720p frame).
  for (const Cavity& cavity : anatomy.cavities) {
    if (cavity.name == "right_ventricle") continue;
    for (const Eigen::Vector3i& t : cavity.lining) anatomy.enclosed_vertices.insert(anatomy.enclosed_vertices.end(), {t[0], t[1], t[2]});
  }
  for (const Valve& valve : anatomy.valves) {
    if (valve.opens_on_filling) anatomy.enclosed_vertices.insert(anatomy.enclosed_vertices.end(), valve.vertices.begin(), valve.vertices.end());
  }
  std::sort(anatomy.enclosed_vertices.begin(), anatomy.enclosed_vertices.end());
  anatomy.enclosed_vertices.erase(std::unique(anatomy.enclosed_vertices.begin(), anatomy.enclosed_vertices.end()),
                                  anatomy.enclosed_vertices.end());
  for (const Wall* wall : {&left, &right}) anatomy.muscle.insert(anatomy.muscle.end(), wall->triangles().begin(), wall->triangles().end());
  VentricleLandmarks& lv = anatomy.left_ventricle;
  const int per_key = left.shape().draw_rows_per_key, columns = left.draw_columns();
  lv.apex = left.drawn(1, 0, 0);
  const int annulus = left.draw_row_of_key(kAnnulusKey), middle = (3 * per_key + 4 * per_key) / 2;
  // Segments go round from the septum's middle (around 0: towards the right heart) through
  // the anterior wall, whichever way round that is in the wall's frame.
  const double to_anterior = layout_.anterior.dot(left.shape().e2) >= 0 ? 1.0 : -1.0;
  for (int c = 0; c < columns; ++c) {
    lv.annulus.push_back(left.drawn(0, annulus, c));
    lv.wall.emplace_back(left.drawn(0, middle, c), left.drawn(1, middle, c));
    double from_septum = to_anterior * 2 * kPi * c / columns;
    from_septum -= 2 * kPi * std::floor(from_septum / (2 * kPi));
    constexpr int kSegmentFromSeptum[6] = {8, 7, 12, 11, 10, 9};
    lv.wall_segment.push_back(kSegmentFromSeptum[std::min(5, static_cast<int>(from_septum / (kPi / 3)))]);
    lv.apical_ring.push_back(left.drawn(1, 2 * per_key, c));
    lv.basal_ring.push_back(left.drawn(1, 5 * per_key, c));
  }
}

OrganMesh Heart::build() {
  const Wall left = make_left();
  const Wall right = make_right(left);
  const Layout& l = layout_;
  // Great vessels, cut off as stubs: the aorta from the left ventricle's base, in front of
  // the mitral annulus and behind the pulmonary trunk, which rises from the right
  // ventricle's outflow towards the left; the venae cavae enter the right atrium from above
  // and below, the pulmonary veins the left atrium from behind.
  const WallShape& ls = left.shape();
  const WallShape& rs = right.shape();
  const Vec aorta_root = left.point({around_towards(ls, (l.anterior + 0.8 * l.to_right_heart).normalized()),
                                     kAnnulusAlong - 0.02, 0.3});
  const Wall aorta = make_vessel("aorta", aorta_root, Vec(-0.12, 1, -0.12), 12.5 * mm, 2 * mm, 55 * mm);
  const Vec trunk_root = right.point({around_towards(rs, (l.anterior + 0.5 * l.left).normalized()), kAnnulusAlong - 0.1, 0.3});
  const Wall trunk = make_vessel("pulmonary_trunk", trunk_root, Vec(0.35, 1, -0.2), 12 * mm, 1.8 * mm, 45 * mm);
  const Vec svc_root = right.point({around_towards(rs, Vec::UnitY()), 0.9, 0.3});
  const Wall svc = make_vessel("superior_vena_cava", svc_root, Vec(0.05, 1, -0.05), 10 * mm, 1.5 * mm, 40 * mm);
  const Vec ivc_root = right.point({around_towards(rs, Vec(0, -1, -0.6).normalized()), 0.66, 0.3});
  const Wall ivc = make_vessel("inferior_vena_cava", ivc_root, Vec(0.05, -1, -0.25), 11.5 * mm, 1.5 * mm, 30 * mm);
  std::vector<Wall> veins;
  for (const double side : {-1.0, 1.0}) {
    const Vec back = (-l.anterior + 0.7 * side * l.left).normalized();
    const Vec root = left.point({around_towards(ls, back), 0.8, 0.3});
    veins.push_back(make_vessel("pulmonary_veins", root, back + Vec(0, 0.2, 0), 6 * mm, 1.2 * mm, 22 * mm));
  }
  glue_root(aorta, left);
  glue_root(trunk, right);
  glue_root(svc, right);
  glue_root(ivc, right);
  for (const Wall& vein : veins) glue_root(vein, left);

  add_valve(left, kAnnulusAlong, 2, "mitral_valve", "left_ventricle", true);
  add_valve(right, kAnnulusAlong, 3, "tricuspid_valve", "right_ventricle", true);
  add_valve(aorta, 0.15, 3, "aortic_valve", "left_ventricle", false);
  add_valve(trunk, 0.15, 3, "pulmonary_valve", "right_ventricle", false);

  // Coronary arteries: the anterior descending in the anterior interventricular groove, the
  // circumflex in the left atrioventricular groove, the right coronary in the right one.
  const double groove = around_towards(ls, (l.anterior + 0.45 * l.to_right_heart).normalized());
  const double sense = std::sin(groove) >= 0 ? 1.0 : -1.0;  // The way round from the groove to the lateral wall.
  add_coronary(left, {{groove, kAnnulusAlong - 0.03}, {groove + 0.1 * sense, 0.3}, {groove + 0.25 * sense, 0.1}}, 1.6 * mm);
  add_coronary(left, {{groove, kAnnulusAlong - 0.02}, {groove + 1.4 * sense, kAnnulusAlong - 0.015},
                      {groove + 2.6 * sense, kAnnulusAlong - 0.02}}, 1.5 * mm);
  const double right_start = around_towards(rs, (l.anterior - 0.3 * l.to_right_heart).normalized());
  add_coronary(right, {{right_start, kAnnulusAlong - 0.02}, {right_start + 1.2, kAnnulusAlong - 0.015},
                       {right_start + 2.4, kAnnulusAlong - 0.02}}, 1.6 * mm);

  add_cavities_and_landmarks(left, right);
  OrganMesh mesh = builder_.finish();
  // Centre the heart's bounding box on the origin.
  Vec lo = mesh.surface.positions.front(), hi = lo;
  for (const Vec& p : mesh.surface.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec shift = -0.5 * (lo + hi);
  for (Vec& p : mesh.surface.positions) p += shift;
  for (Vec& p : mesh.anatomy.myocardium.nodes) p += shift;
  for (Valve& v : mesh.anatomy.valves) {
    for (Vec& p : v.open_positions) p += shift;
  }
  return mesh;
}

}  // namespace

OrganMesh anatomical_heart(int detail) { return Heart(detail).build(); }

}  // namespace systole::mesh::procedural
