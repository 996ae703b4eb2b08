#pragma once
// A small recording for the exporters' tests: an icosphere "beating" with a known periodic
// motion of a few shapes (a breathing mode, a squeeze along y, a travelling twist), in
// two regions, sampled over whole cycles as a loop.

#include <cmath>
#include <random>

#include "export/recording.h"
#include "support/shapes.h"

namespace systole::test {

inline exporter::Recording beating_sphere(int frames = 24, bool loop = true, double noise_m = 0) {
  const mesh::TriangleMesh s = icosphere(0.04, 2);
  exporter::Recording rec;
  rec.scene_name = "sphere";
  rec.fps = 24;
  rec.frame_s = 1.0 / 24;
  rec.loop = loop;
  exporter::OrganTrack t;
  t.name = "sphere";
  t.triangles = s.triangles;
  t.region_names = {"top", "bottom"};
  t.region_colors = {scene::Color(0.8, 0.2, 0.2), scene::Color(0.2, 0.3, 0.8)};
  t.rest_m.resize(3, static_cast<Eigen::Index>(s.positions.size()));
  for (std::size_t v = 0; v < s.positions.size(); ++v) {
    t.rest_m.col(static_cast<Eigen::Index>(v)) = s.positions[v];
    t.vertex_region.push_back(s.positions[v].y() > 0 ? 0 : 1);
  }
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0, 1);
  for (int f = 0; f < frames; ++f) {
    const double phase = 2 * M_PI * f / frames;
    Eigen::Matrix3Xd x = t.rest_m;
    for (Eigen::Index v = 0; v < x.cols(); ++v) {
      const Eigen::Vector3d p = t.rest_m.col(v);
      x.col(v) = p * (1 + 0.08 * std::sin(phase));                           // breathing
      x(1, v) *= 1 - 0.05 * std::cos(2 * phase);                             // squeeze
      const double a = 0.2 * std::sin(phase + 3 * p.y() / 0.04);              // twist, varying with height
      const double cx = x(0, v), cz = x(2, v);
      x(0, v) = std::cos(a) * cx - std::sin(a) * cz;
      x(2, v) = std::sin(a) * cx + std::cos(a) * cz;
      if (noise_m > 0) x.col(v) += noise_m * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    }
    t.frames_m.push_back(x);
    t.activation.push_back({0.5 + 0.5 * std::sin(phase), 0.5 - 0.5 * std::sin(phase)});
  }
  rec.organs.push_back(t);
  return rec;
}

}  // namespace systole::test
