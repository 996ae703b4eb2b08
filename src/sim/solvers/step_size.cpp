#include "sim/solvers/step_size.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sim/drive.h"

namespace systole::sim {
namespace {

constexpr double kStepsPerPeriod = 20;  // Fastest drive component sampled this finely.

constexpr double kMaxContractionPerSubstep = 0.005;  // XPBD: rest lengths move <= 0.5% per substep.

/// Fastest change of any region's contraction a * phi(t), sampled over two periods of the
/// slowest-start rate (and the ramp's end rate). unit: 1/s
double max_contraction_rate_per_s(const Model& m) {
  double fastest = 0;
  for (const auto& r : m.regions) {
    const auto& d = r.drive;
    if (d.waveform == Waveform::kNone || d.amplitude == 0) continue;
    const double rate = std::max(d.rate_hz, d.rate_end_hz);
    const int samples = 2048;
    for (int i = 0; i < samples; ++i) {
      const double u0 = double(i) / samples, u1 = double(i + 1) / samples;
      const double slope = std::abs(waveform_value(d, u1) - waveform_value(d, u0)) * samples * rate;
      fastest = std::max(fastest, d.amplitude * slope);
    }
  }
  return fastest;
}

/// The shortest damping time of a particle, m / (c summed over its springs), over the free
/// particles: XPBD's one Gauss-Seidel pass per substep carries the dampers correctly only
/// for substeps below it (docs/accuracy.md: on a heart-like body 8 % of the motion at 0.8
/// of it, 26 % at 3 times it). unit: s
double shortest_damping_time_s(const Model& m) {
  Eigen::VectorXd c_sum = Eigen::VectorXd::Zero(m.particle_count());
  const Springs& sp = m.springs;
  for (int j = 0; j < sp.size(); ++j) {
    const double c = sp.damping_s[j] / sp.compliance_m_per_N[j];
    c_sum[sp.a[j]] += c;
    c_sum[sp.b[j]] += c;
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.particle_count(); ++i) {
    if (m.inverse_mass[i] > 0 && c_sum[i] > 0) shortest = std::min(shortest, 1.0 / (m.inverse_mass[i] * c_sum[i]));
  }
  return shortest;
}

}  // namespace

double highest_drive_frequency_hz(const std::vector<RegionParams>& regions) {
  double f = 0;
  for (const auto& r : regions) f = std::max(f, highest_frequency_hz(r.drive));
  return f;
}

double max_step_s(const std::vector<RegionParams>& regions) {
  const double f = highest_drive_frequency_hz(regions);
  return f > 0 ? 1.0 / (kStepsPerPeriod * f) : 1.0;
}

double max_omega_squared(const Model& m) {
  Eigen::VectorXd stiffness_sum = Eigen::VectorXd::Zero(m.particle_count());
  const Springs& sp = m.springs;
  for (int j = 0; j < sp.size(); ++j) {
    const double k = 1.0 / sp.compliance_m_per_N[j];
    stiffness_sum[sp.a[j]] += 2 * k;
    stiffness_sum[sp.b[j]] += 2 * k;
  }
  for (const Grab& g : m.grabs) {
    for (int i : g.particles) stiffness_sum[i] += 1.0 / g.compliance_m_per_N;
  }
  double omega2 = 0;
  for (int i = 0; i < m.particle_count(); ++i) omega2 = std::max(omega2, m.inverse_mass[i] * stiffness_sum[i]);
  return omega2;
}

StepLimits step_limits(const Model& m) {
  StepLimits limits;
  const double f = highest_drive_frequency_hz(m.regions);
  limits.max_step_s = max_step_s(m.regions);
  char text[256];
  std::snprintf(text, sizeof text, "drive up to %.3g Hz needs steps <= %.3g ms", f, 1e3 * limits.max_step_s);
  limits.reason = text;

  switch (m.method) {
    case Method::kImplicit:
      limits.max_substep_s = limits.max_step_s;
      limits.reason += "; implicit Euler is stable at any step";
      break;
    case Method::kProjective:
      limits.max_substep_s = limits.max_step_s;
      limits.reason += "; projective dynamics is stable at any step";
      break;
    case Method::kExplicit: {
      const double omega2 = max_omega_squared(m);
      double tau = 0;
      for (double d : m.springs.damping_s) tau = std::max(tau, d);
      // Largest h with h^2 w^2 + 2 h tau w^2 <= 4, times a 0.8 margin.
      const double h = omega2 > 0 ? 0.8 * (-tau + std::sqrt(tau * tau + 4.0 / omega2)) : limits.max_step_s;
      limits.max_substep_s = std::min(h, limits.max_step_s);
      std::snprintf(text, sizeof text, "; stiffest mode %.3g rad/s with %.3g ms damping needs substeps <= %.3g us",
                    std::sqrt(omega2), 1e3 * tau, 1e6 * h);
      limits.reason += text;
      break;
    }
    case Method::kXpbd: {
      // XPBD is stable at any substep; its error grows with how far the constraints'
      // targets move within one substep, so the drive's fastest rest-length change sets it.
      const double rate = max_contraction_rate_per_s(m) / kMaxContractionPerSubstep;
      limits.max_substep_s = rate > 0 ? std::min(1.0 / rate, limits.max_step_s) : limits.max_step_s;
      std::snprintf(text, sizeof text, "; rest lengths change up to %.3g%%/s, <= %.2g%% per substep needs >= %.0f substeps/s",
                    100 * max_contraction_rate_per_s(m), 100 * kMaxContractionPerSubstep, rate);
      limits.reason += text;
      // Its dampers, one Gauss-Seidel pass each substep, are accurate only for substeps up
      // to the particles' damping time m / c.
      const double damping_s = shortest_damping_time_s(m);
      if (damping_s < limits.max_substep_s) {
        limits.max_substep_s = damping_s;
        std::snprintf(text, sizeof text, "; dampers with a %.3g us damping time need substeps <= %.3g us",
                      1e6 * damping_s, 1e6 * limits.max_substep_s);
        limits.reason += text;
      }
      break;
    }
  }
  return limits;
}

double estimated_cost_s_per_s(const Model& model, double dt_s) {
  const double work = model.springs.size() + (model.volume.enabled ? double(model.volume.triangles.size()) : 0.0);
  switch (model.method) {
    case Method::kXpbd: return work * model.substeps / dt_s / 74e6;
    case Method::kExplicit: return work * model.substeps / dt_s / 95e6;
    case Method::kImplicit: return work / dt_s / 0.2e6;
    case Method::kProjective: return work * model.substeps * (model.iterations + 1) / dt_s / 50e6;
  }
  return 0;
}

}  // namespace systole::sim
