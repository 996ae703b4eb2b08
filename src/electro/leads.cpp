#include "electro/leads.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace systole::electro {
namespace {

constexpr double kAmplitudeMv = 100;  ///< Rest -85 mV to the plateau's +15 mV.
/// No beat's excitation and action potential last longer than this after it starts. unit: s
constexpr double kLongestBeatS = 2.0;
constexpr double kUpstrokeS = 0.0015;  ///< Logistic scale: 10-90 % in 6.6 ms.
constexpr double kRepolarisationS = 0.014;  ///< Logistic scale: 10-90 % in 62 ms.
/// sigma_i / (4 pi sigma_e): intracellular conductivity 0.17 S/m along the fibres (Clerc
/// 1976, J Physiol 255:335), the torso's mean 0.2 S/m (Geddes & Baker 1967, Med Biol Eng 5:271).
constexpr double kSourceGain = 0.17 / (4 * std::numbers::pi * 0.2);

double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }

/// Per excitable node, how much of its Vm each electrode sees: G_i = -k sum over its springs
/// of w (1/R_i - 1/R_other), w a spring's share of the muscle's volume over its length
/// squared, scaled so sum w L^2 = 3 V (a uniform gradient's integral over the volume).
/// unit: 1 / m (times mV gives mV)
std::vector<std::array<double, 9>> lead_field(const mesh::Myocardium& m, const Excitation& ex,
                                              const std::array<Eigen::Vector3d, 9>& at) {
  const std::size_t n = m.nodes.size();
  double volume = 0, weighted = 0;
  for (std::size_t i = 0; i < n; ++i) volume += ex.excitable(static_cast<int>(i)) ? m.node_volume_m3[i] : 0.0;
  const auto source = [&](std::size_t j) {
    const auto [a, b] = m.springs[j];
    return m.fibre_share[j] >= 0 && ex.excitable(a) && ex.tissue[static_cast<std::size_t>(a)] == ex.tissue[static_cast<std::size_t>(b)];
  };
  for (std::size_t j = 0; j < m.springs.size(); ++j) {
    if (source(j)) weighted += m.spring_weight[j] * (m.nodes[static_cast<std::size_t>(m.springs[j].first)] - m.nodes[static_cast<std::size_t>(m.springs[j].second)]).squaredNorm();
  }
  const double scale = weighted > 0 ? 3 * volume / weighted : 0.0;
  std::vector<std::array<double, 9>> g(n, std::array<double, 9>{});
  for (std::size_t j = 0; j < m.springs.size(); ++j) {
    if (!source(j)) continue;
    const auto [a, b] = m.springs[j];
    const double w = kSourceGain * scale * m.spring_weight[j];
    for (std::size_t e = 0; e < at.size(); ++e) {
      const double d = 1.0 / (at[e] - m.nodes[static_cast<std::size_t>(a)]).norm() - 1.0 / (at[e] - m.nodes[static_cast<std::size_t>(b)]).norm();
      g[static_cast<std::size_t>(a)][e] -= w * d;
      g[static_cast<std::size_t>(b)][e] += w * d;
    }
  }
  return g;
}

/// The electrodes' places in the organ's coordinates: about the excitable muscle's centre.
std::array<Eigen::Vector3d, 9> placed(const mesh::OrganMesh& mesh, const Excitation& ex, const Electrodes& e) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (ex.excitable(static_cast<int>(i))) centre += m.nodes[i], ++count;
  }
  centre /= std::max(count, 1);
  const Eigen::Matrix3d& axes = mesh.anatomy.body_axes;
  std::array<Eigen::Vector3d, 9> at = {e.right_arm, e.left_arm, e.left_leg, e.chest[0], e.chest[1],
                                       e.chest[2],  e.chest[3], e.chest[4], e.chest[5]};
  for (Eigen::Vector3d& x : at) x = centre + axes * x;
  return at;
}

/// The twelve leads from the nine electrodes' potentials (RA, LA, LL, V1..V6).
std::array<double, 12> leads_of(const std::array<double, 9>& phi) {
  const double ra = phi[0], la = phi[1], ll = phi[2], wilson = (ra + la + ll) / 3;
  return {la - ra,           ll - ra,           ll - la,           ra - (la + ll) / 2, la - (ra + ll) / 2,
          ll - (ra + la) / 2, phi[3] - wilson, phi[4] - wilson, phi[5] - wilson, phi[6] - wilson,
          phi[7] - wilson,    phi[8] - wilson};
}

}  // namespace

Electrodes standard_electrodes() {
  // The heart's centre lies just left of the midline (its apex, 5-6 cm further left, at the
  // midclavicular line), about 6 cm behind the front of the chest at the fourth and fifth
  // intercostal spaces.
  constexpr double mid = -0.005;
  Electrodes e;
  e.right_arm = {mid - 0.15, 0.13, 0.05};  // Infraclavicular fossae (Mason & Likar 1966).
  e.left_arm = {mid + 0.15, 0.13, 0.05};
  e.left_leg = {mid + 0.12, -0.25, 0.06};  // Left anterior axillary line, below the costal margin.
  // V1 and V2 lie on the sternum's borders, in front of the right ventricle with the
  // sternum and the chest wall between: 2.5 cm further forward than the chest's curve
  // through V3-V6 would put them, so the right ventricle's nearest wall does not swamp them.
  e.chest = {Eigen::Vector3d(mid - 0.025, 0.02, 0.085),   // V1: 4th space, right sternal border.
             Eigen::Vector3d(mid + 0.025, 0.02, 0.09),    // V2: 4th space, left sternal border.
             Eigen::Vector3d(mid + 0.0575, 0.0025, 0.062),  // V3: midway V2-V4.
             Eigen::Vector3d(mid + 0.09, -0.015, 0.055),  // V4: 5th space, midclavicular line.
             Eigen::Vector3d(mid + 0.13, -0.015, 0.025),  // V5: anterior axillary line, V4's level.
             Eigen::Vector3d(mid + 0.15, -0.015, -0.02)};  // V6: midaxillary line.
  return e;
}

double action_potential_mv(double since_s, double duration_s) {
  // Each logistic step is taken as settled 10 scales from its middle (within 5e-5): outside
  // both windows the node rests or is on its plateau, and no exponential is needed.
  const double rise = 10 * kUpstrokeS, fall = 10 * kRepolarisationS;
  if (since_s < -rise || since_s > duration_s + fall) return 0.0;
  const double up = since_s < rise ? logistic(since_s / kUpstrokeS) : 1.0;
  const double down = since_s > duration_s - fall ? logistic((since_s - duration_s) / kRepolarisationS) : 0.0;
  return kAmplitudeMv * up * (1.0 - down);
}

Ecg compute_ecg(const mesh::OrganMesh& mesh, const Excitation& ex, const std::vector<double>& beat_start_s,
                double from_s, double to_s, double rate_hz, const Electrodes& electrodes) {
  const mesh::Myocardium& m = mesh.anatomy.myocardium;
  const std::vector<std::array<double, 9>> g = lead_field(m, ex, placed(mesh, ex, electrodes));
  Ecg ecg;
  ecg.rate_hz = rate_hz;
  ecg.start_s = from_s;
  ecg.leads = standard_leads();
  const std::size_t samples = static_cast<std::size_t>(std::max(0.0, std::ceil((to_s - from_s) * rate_hz - 1e-9)));
  ecg.mv.assign(12, std::vector<double>(samples, 0.0));
  const std::size_t beats = beat_start_s.size();
  // Each beat's restitution, once: a node's action potential lasts its 1-s duration times it.
  std::vector<double> restitution(beats);
  for (std::size_t k = 0; k < beats; ++k) {
    const double cycle = k + 1 < beats ? beat_start_s[k + 1] - beat_start_s[k]
                                       : (k > 0 ? beat_start_s[k] - beat_start_s[k - 1] : 1.0);
    restitution[k] = action_potential_s(1.0, cycle);
  }
  for (std::size_t s = 0; s < samples; ++s) {
    const double t = from_s + double(s) / rate_hz;
    std::array<double, 9> phi{};
    // Only beats that started within an action potential's reach of t can be under way.
    const std::size_t first = static_cast<std::size_t>(
        std::lower_bound(beat_start_s.begin(), beat_start_s.end(), t - kLongestBeatS) - beat_start_s.begin());
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      if (std::isnan(ex.activation_s[i])) continue;
      double vm = 0;
      for (std::size_t k = first; k < beats; ++k) {
        const double since = t - beat_start_s[k] - ex.activation_s[i];
        if (since < -0.1) break;
        vm += action_potential_mv(since, ex.duration_1s_s[i] * restitution[k]);
      }
      if (vm != 0)
        for (std::size_t e = 0; e < 9; ++e) phi[e] += g[i][e] * vm;
    }
    const std::array<double, 12> leads = leads_of(phi);
    for (std::size_t l = 0; l < 12; ++l) ecg.mv[l][s] = leads[l];
  }
  return ecg;
}

}  // namespace systole::electro
