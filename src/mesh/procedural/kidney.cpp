// The procedural kidney: a left kidney, about 11 cm long, 6 cm wide and 4 cm thick. A
// bean: an ellipsoid whose medial border (-X, towards the spine) is hollowed into the
// renal hilum, from which the renal vein (in front), the renal artery (behind it, a little
// higher) and the renal pelvis narrowing into the ureter (behind, running down) leave as
// stubs. The long axis leans so the upper pole sits nearer the midline, as in the body.
// Parts: the cortex split along the long axis into upper_pole, interpolar and lower_pole,
// and hilum (the vessel and ureter stubs: pinned in a scene, as the renal pedicle holds
// the kidney).
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

enum Part : int { kUpperPole, kInterpolar, kLowerPole, kHilum, kPartCount };

const char* const kPartNames[kPartCount] = {"upper_pole", "interpolar", "lower_pole", "hilum"};

// The mesher's centre, inside the cortex near the hilum: seen from closer, the stubs span a
// wider angle, which the mesher's rays resolve better. unit: m
const Vec kCenter(-0.004, 0.0, 0.0);

/// The long axis: tilted 12 degrees so the upper pole leans medially (-X).
Vec long_axis() {
  const double tilt = 12.0 * M_PI / 180.0;
  return Vec(-std::sin(tilt), std::cos(tilt), 0.0);
}

// A stub from inside the body out along the ray from the centre through `end`: keeps the
// surface star-shaped about the centre. A slight flare (radius_end >= radius_from) keeps its
// wall from running exactly along the rays.
Primitive radial_stub(const Vec& end, double radius_from, double radius_end, double blend) {
  return round_cone(kHilum, kCenter + 0.2 * (end - kCenter), radius_from, end, radius_end, blend);
}

Field kidney_field() {
  Field field;
  std::vector<Primitive>& p = field.primitives;
  const Eigen::Matrix3d axes = axes_along(long_axis(), Vec::UnitX());  // Columns: long, lateral, anterior.
  p.push_back(ellipsoid(kInterpolar, Vec(0.006, 0.0, 0.0), axes, Vec(0.056, 0.030, 0.020), 0));
  // The hilum: a vertical slit hollowed out of the medial border.
  p.push_back(carved(ellipsoid(kInterpolar, Vec(-0.036, -0.002, 0.001), axes, Vec(0.028, 0.024, 0.032), 0.006)));
  // The renal vessels (vein and artery as one short, thick stub), and below and behind
  // them the renal pelvis narrowing into the ureter. Stubs thinner than about a tenth of
  // their distance from the centre would be seen edge-on by the mesher's rays.
  p.push_back(radial_stub(Vec(-0.046, 0.006, 0.003), 0.0080, 0.0088, 0.005));
  p.push_back(radial_stub(Vec(-0.040, -0.022, -0.007), 0.0075, 0.0062, 0.005));
  return field;
}

}  // namespace

OrganMesh kidney(int detail) {
  const Vec axis = long_axis();
  const double pole_from = 0.024;  // m from the centre along the long axis: the poles' cortex.
  return mesh_organ_surface(kidney_field(), kCenter, 0.1, detail, kPartNames, [&](const Vec& x, int part) -> int {
    if (part == kHilum) return part;
    const double along = (x - kCenter).dot(axis);
    return along > pole_from ? kUpperPole : along < -pole_from ? kLowerPole : kInterpolar;
  });
}

}  // namespace systole::mesh::procedural
