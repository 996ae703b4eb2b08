// The procedural lungs: two closed surfaces (right and left lung) and the airway (trachea
// and both main bronchi, tucked into each lung's hilum) as a third, each meshed by the
// implicit mesher about its own centre, lobes from the fissure planes.
//
// Frame: +Y towards the head, +Z anterior (the viewer), +X the patient's left. Each lung
// is a blunt cone: a rounded apex above the clavicle, a broad base hollowed by the dome of
// the diaphragm (higher on the right, over the liver), and a medial face hollowed by the
// heart - deeper on the left, whose anterior border also has the cardiac notch above the
// lingula. The left lung is the smaller. The oblique fissure (both lungs) runs from high at
// the back down to the front of the base and sets the lower lobe off; on the right the
// horizontal fissure splits the rest into upper and middle lobes.
//
// Why separate components: a lung is not star-shaped about any point of the airway (rays
// from the carina leave a bronchus and enter a lung), so each piece is meshed on its own:
// the two lungs, and the trachea and the two main bronchi as three capsules overlapping at
// the carina. One organ keeps one volume constraint over all of them, as the shared
// pleural pressure does; the bronchi end inside the lungs, so the pieces look joined.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "mesh/procedural/implicit_mesher.h"
#include "mesh/procedural/organs.h"
#include "mesh/procedural/sdf.h"

namespace systole::mesh::procedural {
namespace {

using Vec = Eigen::Vector3d;
using Mat = Eigen::Matrix3d;

enum Part : int {
  kRightUpperLobe,
  kRightMiddleLobe,
  kRightLowerLobe,
  kLeftUpperLobe,
  kLeftLowerLobe,
  kTrachea,
  kPartCount
};

const char* const kPartNames[kPartCount] = {"right_upper_lobe", "right_middle_lobe", "right_lower_lobe",
                                            "left_upper_lobe",  "left_lower_lobe",   "trachea"};

// The heart's place in the mediastinum: both lungs are hollowed around it.
const Vec kHeartCenter(0.012, -0.052, 0.022);
const Vec kHeartRadii(0.048, 0.058, 0.058);

/// One lung; `side` is -1 for the right (patient's right, -X) and +1 for the left.
Field lung_field(int side) {
  const double s = side;
  const bool right = side < 0;
  const double width = right ? 0.062 : 0.056;   // Half-width of the base. unit: m
  const double dome = right ? -0.162 : -0.172;  // Centre of the carving diaphragm dome. unit: m
  Field field;
  std::vector<Primitive>& p = field.primitives;
  const int part = right ? kRightUpperLobe : kLeftUpperLobe;  // Reassigned by the fissures below.
  // Broad lower body, deeper at the back, then the cone up to the apex.
  p.push_back(ellipsoid(part, Vec(s * 0.080, -0.040, -0.004), Mat::Identity(), Vec(width, 0.078, 0.088), 0));
  p.push_back(round_cone(part, Vec(s * 0.078, -0.020, -0.006), 0.056, Vec(s * 0.063, 0.097, -0.012), 0.031, 0.030));
  // Ribs round the back: a posterior bulge near the spine.
  p.push_back(ellipsoid(part, Vec(s * 0.058, -0.020, -0.052), Mat::Identity(), Vec(0.030, 0.070, 0.035), 0.025));
  // The diaphragm's dome hollows the base.
  p.push_back(carved(ellipsoid(part, Vec(s * 0.074, dome, 0.002), Mat::Identity(), Vec(0.085, 0.078, 0.100), 0.014)));
  // The heart hollows the medial face.
  p.push_back(carved(ellipsoid(part, kHeartCenter, Mat::Identity(), kHeartRadii, 0.012)));
  if (!right) {
    // The cardiac notch: a bite out of the anterior border above the lingula.
    p.push_back(carved(ellipsoid(part, Vec(0.034, -0.048, 0.080), Mat::Identity(), Vec(0.030, 0.030, 0.034), 0.010)));
  }
  return field;
}

/// One tube of the airway as its own closed piece (a capsule), meshed about its middle:
/// from there its wall is seen at a healthy angle, where rays from the carina along a
/// branch would graze it. The three tubes overlap at the carina.
Field airway_tube(const Vec& from, double radius_from, const Vec& to, double radius_to) {
  Field field;
  field.primitives.push_back(round_cone(kTrachea, from, radius_from, to, radius_to, 0));
  return field;
}

/// The lobe of a lung vertex from the fissure planes.
int lobe(const Vec& x) {
  // Oblique fissure, seen from the side: from (z -8 cm, y +7 cm) at the back to
  // (z +7 cm, y -10 cm) at the front of the base; the lower lobe lies behind and below it.
  const Vec oblique_point(0.0, -0.012, -0.005);
  const Vec oblique_normal = Vec(0.0, -0.15, -0.17).normalized();
  const bool lower = (x - oblique_point).dot(oblique_normal) > 0;
  if (x.x() < 0) {
    if (lower) return kRightLowerLobe;
    return x.y() > 0.002 ? kRightUpperLobe : kRightMiddleLobe;  // The horizontal fissure.
  }
  return lower ? kLeftLowerLobe : kLeftUpperLobe;
}

void append(OrganMesh& mesh, const TriangleMesh& piece, int fixed_part) {
  const int offset = static_cast<int>(mesh.surface.positions.size());
  for (const Vec& x : piece.positions) {
    mesh.surface.positions.push_back(x);
    mesh.vertex_part.push_back(fixed_part >= 0 ? fixed_part : lobe(x));
  }
  for (const Eigen::Vector3i& t : piece.triangles) mesh.surface.triangles.push_back(t + Eigen::Vector3i::Constant(offset));
}

}  // namespace

OrganMesh lungs(int detail) {
  const int total = target_triangles(detail);
  const Vec carina(0.0, 0.046, -0.015);
  // The trachea, and the right main bronchus, shorter and steeper than the left.
  const Vec trachea_top(0.0, 0.140, -0.022), right_end(-0.046, 0.010, -0.016), left_end(0.050, 0.002, -0.018);
  struct Piece {
    Field field;
    Vec center;
    double share;  // Of the triangle budget, about the share of the surface area (lungs only).
    int part;      // -1: lobes from the fissures.
  };
  const Piece pieces[] = {
      {lung_field(-1), Vec(-0.080, -0.020, -0.008), 0.53, -1},
      {lung_field(+1), Vec(0.086, -0.030, -0.012), 0.47, -1},
      {airway_tube(carina, 0.0092, trachea_top, 0.0095), 0.5 * (carina + trachea_top), 0, kTrachea},
      {airway_tube(carina, 0.0082, right_end, 0.0078), 0.5 * (carina + right_end), 0, kTrachea},
      {airway_tube(carina, 0.0076, left_end, 0.0070), 0.5 * (carina + left_end), 0, kTrachea},
  };
  OrganMesh mesh;
  mesh.part_names.assign(kPartNames, kPartNames + kPartCount);
  for (const Piece& piece : pieces) {
    MesherSettings settings;
    settings.center = piece.center;
    settings.bound_radius = 0.2;
    // The airway's tubes keep one resolution at every detail (about 450 triangles each,
    // 3 mm edges): the stub is pinned, so finer buys nothing, and at some counts the
    // remesher folds the wall of a tube seen nearly edge-on (tests/mesh/organs_test.cpp
    // checks every detail).
    settings.target_triangles =
        piece.part == kTrachea ? 400 : std::max(160, static_cast<int>(std::lround(piece.share * total)));
    append(mesh, mesh_implicit_surface(piece.field, settings), piece.part);
  }
  return mesh;
}

}  // namespace systole::mesh::procedural
