#pragma once
// A sim::Model built by hand: a few particles joined by springs at their rest lengths, with
// nothing else (no regions, damping, drag, volume, floor), for tests whose answer is known
// in closed form (a free fall, a harmonic oscillator).

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "sim/model.h"

namespace systole::test {

/// Particles at `x` (unit: m) with masses `mass_kg`, joined by `springs` (i, j) of stiffness
/// k_N_per_m at their current lengths, each spring its own colour; `substeps` per step.
inline sim::Model spring_body(const Eigen::Matrix3Xd& x, const std::vector<double>& mass_kg,
                              const std::vector<std::pair<int, int>>& springs, double k_N_per_m, int substeps) {
  sim::Model m;
  m.name = "spring body";
  m.substeps = substeps;
  m.iterations = 10;
  m.rest_positions = x;
  m.inverse_mass.resize(static_cast<Eigen::Index>(mass_kg.size()));
  for (std::size_t i = 0; i < mass_kg.size(); ++i) m.inverse_mass[static_cast<Eigen::Index>(i)] = 1.0 / mass_kg[i];
  for (const auto& [a, b] : springs) {
    m.springs.color_begin.push_back(m.springs.size());
    m.springs.a.push_back(a);
    m.springs.b.push_back(b);
    m.springs.rest_m.push_back((x.col(a) - x.col(b)).norm());
    m.springs.compliance_m_per_N.push_back(1.0 / k_N_per_m);
    m.springs.damping_s.push_back(0.0);
    m.springs.region_a.push_back(-1);
    m.springs.region_b.push_back(-1);
  }
  m.springs.color_begin.push_back(m.springs.size());
  m.springs.stretch_count = m.springs.size();
  Eigen::Vector3d lo = x.rowwise().minCoeff(), hi = x.rowwise().maxCoeff();
  m.rest_extent_m = (hi - lo).norm();
  return m;
}

}  // namespace systole::test
