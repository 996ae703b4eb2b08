#include "export/usd.h"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "common/atomic_output.h"

namespace systole::exporter {
namespace {

/// A USD prim name: an identifier (letters, digits, '_', not starting with a digit).
std::string prim_name(const std::string& name) {
  std::string out = name.empty() ? "organ" : name;
  for (char& c : out) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  if (std::isdigit(static_cast<unsigned char>(out.front()))) out = "_" + out;
  return out;
}

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

/// "(x, y, z)" at float precision (nine significant digits read back to the same float).
std::string triple(double x, double y, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", double(float(x)), double(float(y)), double(float(z)));
  return text;
}

void mesh(std::ostream& out, const OrganTrack& organ) {
  out << "    def Mesh \"" << prim_name(organ.name) << "\"\n    {\n";
  out << "        uniform token subdivisionScheme = \"none\"\n";
  out << "        uniform bool doubleSided = " << (organ.closed ? "false" : "true") << "\n";
  out << "        int[] faceVertexCounts = [";
  for (std::size_t t = 0; t < organ.triangles.size(); ++t) out << (t ? ", 3" : "3");
  out << "]\n        int[] faceVertexIndices = [";
  for (std::size_t t = 0; t < organ.triangles.size(); ++t) {
    const auto& tri = organ.triangles[t];
    out << (t ? ", " : "") << tri[0] << ", " << tri[1] << ", " << tri[2];
  }
  out << "]\n";
  // USD's default orientation is right-handed counter-clockwise, as our triangles are.
  out << "        color3f[] primvars:displayColor = [";
  for (std::size_t t = 0; t < organ.triangles.size(); ++t) {
    const int r = triangle_region(organ, organ.triangles[t]);
    const scene::Color c = r < 0 ? organ.body_color : organ.region_colors[static_cast<std::size_t>(r)];
    out << (t ? ", " : "") << triple(srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2]));
  }
  out << "] (\n            interpolation = \"uniform\"\n        )\n";
  // The extent covers every frame, so a bounding box never clips the motion.
  Eigen::Vector3d lo = organ.rest_m.rowwise().minCoeff(), hi = organ.rest_m.rowwise().maxCoeff();
  for (const auto& x : organ.frames_m) {
    lo = lo.cwiseMin(x.rowwise().minCoeff());
    hi = hi.cwiseMax(x.rowwise().maxCoeff());
  }
  out << "        float3[] extent = [" << triple(lo[0], lo[1], lo[2]) << ", " << triple(hi[0], hi[1], hi[2]) << "]\n";
  out << "        point3f[] points = [";
  for (Eigen::Index v = 0; v < organ.rest_m.cols(); ++v) {
    out << (v ? ", " : "") << triple(organ.rest_m(0, v), organ.rest_m(1, v), organ.rest_m(2, v));
  }
  out << "]\n        point3f[] points.timeSamples = {\n";
  for (std::size_t f = 0; f < organ.frames_m.size(); ++f) {
    const auto& x = organ.frames_m[f];
    out << "            " << f << ": [";
    for (Eigen::Index v = 0; v < x.cols(); ++v) out << (v ? ", " : "") << triple(x(0, v), x(1, v), x(2, v));
    out << "],\n";
  }
  out << "        }\n    }\n";
}

}  // namespace

void write_usda(const std::filesystem::path& file, const Recording& rec) {
  write_atomically(file, [&](std::ostream& out) {
    out << "#usda 1.0\n(\n    defaultPrim = \"" << prim_name(rec.scene_name) << "\"\n";
    out << "    doc = \"Systole: " << rec.scene_name << ", " << rec.frame_count() << " frames\"\n";
    out << "    startTimeCode = 0\n    endTimeCode = " << std::max(0, rec.frame_count() - 1) << "\n";
    out << "    timeCodesPerSecond = " << rec.fps << "\n    framesPerSecond = " << rec.fps << "\n";
    out << "    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n\n";
    out << "def Xform \"" << prim_name(rec.scene_name) << "\"\n{\n";
    for (const auto& organ : rec.organs) mesh(out, organ);
    out << "}\n";
  });
}

}  // namespace systole::exporter
