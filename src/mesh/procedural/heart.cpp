// The procedural heart: a smooth union of ellipsoids (chambers, auricles) and tapered
// capsules (vessel stubs), meshed by the implicit mesher, parts from the nearest primitive.
//
// Frame: +Y towards the head, +Z anterior (the viewer), +X the patient's left. The long
// axis runs from the base (atrioventricular groove) down, forward and to the left to the
// apex. The right ventricle forms most of the front, the left ventricle the left border
// and the apex, the right atrium the right border with the venae cavae entering it from
// above and below, the left atrium sits behind with its auricle peeking out on the left,
// and the aorta and pulmonary trunk rise from the top, the trunk in front and to the left.
// Small blend radii between neighbouring chambers leave the grooves of a real heart
// (interventricular, atrioventricular) as creases.

#include <Eigen/Geometry>
#include <cmath>

#include "mesh/procedural/implicit_mesher.h"
#include "mesh/procedural/organs.h"
#include "mesh/procedural/sdf.h"

namespace systole::mesh::procedural {
namespace {

using Vec = Eigen::Vector3d;

enum Part : int {
  kLeftVentricle,
  kRightVentricle,
  kLeftAtrium,
  kRightAtrium,
  kApex,
  kAorta,
  kPulmonaryTrunk,
  kSuperiorVenaCava,
  kInferiorVenaCava,
  kPartCount
};

const char* const kPartNames[kPartCount] = {"left_ventricle", "right_ventricle", "left_atrium",
                                            "right_atrium",   "apex",            "aorta",
                                            "pulmonary_trunk", "superior_vena_cava", "inferior_vena_cava"};

struct HeartFrame {
  Vec base = Vec(0.0, 0.012, 0.0);                       // Centre of the ventricular base. unit: m
  Vec axis = Vec(0.43, -0.82, 0.37).normalized();        // Base to apex.
  Vec anterior, left;                                     // Perpendicular to the axis.
  HeartFrame() {
    anterior = (Vec::UnitZ() - axis * axis.dot(Vec::UnitZ())).normalized();
    left = anterior.cross(axis);
  }
  // A point `along` the long axis from the base, `side` to the patient's left, `front` forwards.
  Vec at(double along, double side, double front) const { return base + along * axis + side * left + front * anterior; }
};

// The centre the mesher casts its rays from: every part of the field is star-shaped
// about it, so the vessels point away from it and the bumps are shallow.
const Vec kCenter(0.000, 0.012, 0.000);

// A vessel stub along the ray from the centre towards `end`, from `from` (a fraction of
// the way, inside the body) to `end`.
Primitive radial_vessel(int part, const Vec& end, double from, double radius_from, double radius_end, double blend) {
  return round_cone(part, kCenter + from * (end - kCenter), radius_from, end, radius_end, blend);
}

Field heart_field(const HeartFrame& h) {
  Field field;
  std::vector<Primitive>& p = field.primitives;
  const Eigen::Matrix3d ventricle_axes = axes_along(h.axis, h.left);
  // Left ventricle: a blunt cone ending in the apex.
  p.push_back(round_cone(kLeftVentricle, h.at(0.014, 0.010, -0.008), 0.032, h.at(0.068, 0.004, 0.000), 0.013, 0));
  // Right ventricle: a flatter, shorter body wrapped over the front and right.
  p.push_back(ellipsoid(kRightVentricle, h.at(0.024, -0.014, 0.012), ventricle_axes, Vec(0.040, 0.030, 0.020), 0.010));
  // Atria behind and above the base; a small blend leaves the atrioventricular groove.
  p.push_back(ellipsoid(kLeftAtrium, Vec(0.008, 0.036, -0.026), Eigen::Matrix3d::Identity(), Vec(0.030, 0.019, 0.022), 0.014));
  p.push_back(ellipsoid(kRightAtrium, Vec(-0.032, 0.028, -0.006), Eigen::Matrix3d::Identity(), Vec(0.021, 0.026, 0.025), 0.012));
  // Auricles: ear-like bumps pointing away from the centre around the great arteries.
  const Vec left_auricle(0.034, 0.036, 0.004), right_auricle(-0.022, 0.042, 0.018);
  p.push_back(ellipsoid(kLeftAtrium, left_auricle, axes_along(left_auricle - kCenter, Vec::UnitY()),
                        Vec(0.014, 0.010, 0.008), 0.008));
  p.push_back(ellipsoid(kRightAtrium, right_auricle, axes_along(right_auricle - kCenter, Vec::UnitY()),
                        Vec(0.014, 0.010, 0.009), 0.016));
  // Great vessels, cut off as stubs: the pulmonary trunk in front and to the left of
  // the aorta, the venae cavae entering the right atrium from above and below.
  p.push_back(radial_vessel(kAorta, Vec(-0.008, 0.084, -0.006), 0.3, 0.0145, 0.0135, 0.010));
  p.push_back(radial_vessel(kPulmonaryTrunk, Vec(0.013, 0.078, 0.011), 0.3, 0.0140, 0.0125, 0.010));
  p.push_back(radial_vessel(kSuperiorVenaCava, Vec(-0.033, 0.076, -0.011), 0.4, 0.0105, 0.0100, 0.008));
  p.push_back(radial_vessel(kInferiorVenaCava, Vec(-0.030, -0.012, -0.026), 0.4, 0.0120, 0.0115, 0.008));
  return field;
}

}  // namespace

OrganMesh heart(int detail) {
  const HeartFrame frame;
  // The apex is the tip of the ventricles: the last stretch of the long axis.
  const double apex_from = 0.060;  // m from the base along the axis.
  const auto apex_or_part = [&](const Vec& x, int part) -> int {
    const bool ventricle = part == kLeftVentricle || part == kRightVentricle;
    return ventricle && (x - frame.base).dot(frame.axis) > apex_from ? kApex : part;
  };
  return mesh_organ_surface(heart_field(frame), kCenter, 0.15, detail, kPartNames, apex_or_part);
}

}  // namespace systole::mesh::procedural
