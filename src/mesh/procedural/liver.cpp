// The procedural liver: about 22 cm wide, 15 cm tall at the right lobe and 13 cm deep. A
// large rounded right lobe (patient's right, -X) and a flat left lobe tapering to a tip
// over the stomach, a domed diaphragmatic surface, and an underside sloping up to a sharp
// anterior-inferior border, below which the fundus of the gallbladder peeks out. The
// inferior vena cava leaves the back of the dome as a stub (pinned in a scene: the
// hepatic veins and ligaments hold the liver under the diaphragm).
// Parts: right_lobe and left_lobe (divided at the falciform ligament), gallbladder,
// inferior_vena_cava.
//
// Frame: +Y towards the head, +Z anterior (the viewer), +X the patient's left.

#include <Eigen/Geometry>
#include <cmath>

#include "mesh/procedural/implicit_mesher.h"
#include "mesh/procedural/organs.h"
#include "mesh/procedural/sdf.h"

namespace systole::mesh::procedural {
namespace {

using Vec = Eigen::Vector3d;
using Mat = Eigen::Matrix3d;

enum Part : int { kRightLobe, kLeftLobe, kGallbladder, kInferiorVenaCava, kPartCount };

const char* const kPartNames[kPartCount] = {"right_lobe", "left_lobe", "gallbladder", "inferior_vena_cava"};

const Vec kCenter(-0.022, 0.012, 0.0);  // The mesher's centre, inside the right lobe. unit: m
/// The falciform ligament's plane: x > this is the left lobe. unit: m
constexpr double kFalciformX = 0.012;

Primitive radial(int part, const Vec& end, double from, double radius_from, double radius_end, double blend) {
  return round_cone(part, kCenter + from * (end - kCenter), radius_from, end, radius_end, blend);
}

Field liver_field() {
  Field field;
  std::vector<Primitive>& p = field.primitives;
  p.push_back(ellipsoid(kRightLobe, Vec(-0.045, 0.005, 0.000), Mat::Identity(), Vec(0.068, 0.078, 0.068), 0));
  // Bulk where the lobes meet, so the outline narrows like a wedge towards the left.
  p.push_back(ellipsoid(kRightLobe, Vec(0.000, 0.020, 0.005), Mat::Identity(), Vec(0.060, 0.055, 0.060), 0.030));
  // The left lobe: flat, tilting down towards its tip.
  const Mat tilt = Eigen::AngleAxisd(-0.15, Vec::UnitZ()).toRotationMatrix();
  p.push_back(ellipsoid(kLeftLobe, Vec(0.060, 0.034, 0.012), tilt, Vec(0.066, 0.028, 0.050), 0.030));
  // The inferior border slants up from the right lobe's lowest point to the left lobe's
  // tip (18 degrees): a flat, wide ellipsoid carved from below.
  const double slope = 0.314;
  const Mat along_border = Eigen::AngleAxisd(slope, Vec::UnitZ()).toRotationMatrix();
  const Vec border_middle(0.005, -0.0375, 0.0);
  p.push_back(carved(ellipsoid(kRightLobe, border_middle - 0.1 * along_border.col(1), along_border,
                               Vec(0.30, 0.10, 0.30), 0.020)));
  // The gallbladder's fundus just below the border, in front.
  const Vec fundus(-0.010, -0.052, 0.045);
  p.push_back(ellipsoid(kGallbladder, kCenter + 0.72 * (fundus - kCenter), axes_along(fundus - kCenter, Vec::UnitX()),
                        Vec(0.030, 0.013, 0.013), 0.006));
  // The inferior vena cava leaving the back of the dome: a short stub, below the right
  // lobe's top, so the dome's top meets the diaphragm first (scenes/chest.yaml).
  p.push_back(radial(kInferiorVenaCava, Vec(-0.012, 0.045, -0.062), 0.5, 0.0120, 0.0110, 0.010));
  return field;
}

}  // namespace

OrganMesh liver(int detail) {
  return mesh_organ_surface(liver_field(), kCenter, 0.2, detail, kPartNames, [](const Vec& x, int part) -> int {
    if (part == kRightLobe || part == kLeftLobe) return x.x() > kFalciformX ? kLeftLobe : kRightLobe;
    return part;
  });
}

}  // namespace systole::mesh::procedural
