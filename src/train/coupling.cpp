#include "train/coupling.h"

#include <Eigen/Dense>
#include <algorithm>

#include "sim/forces.h"
#include "sim/solvers/step.h"
#include "world/frame_source.h"

namespace systole::train {
namespace {

/// Normal equations of a few columns solved with a small ridge (relative to the largest
/// diagonal): a region the data cannot see stays at 0 change.
Eigen::VectorXd ridge_solve(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& rhs, double ridge) {
  Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  normal.diagonal().array() += ridge * (normal.diagonal().maxCoeff() + 1e-30);
  return normal.ldlt().solve(jacobian.transpose() * rhs);
}

/// The two signals' solves at a recorded step, their matrices and the springs they read
/// built once for the whole recording.
class SpringFits {
 public:
  SpringFits(const sim::Model& model, const std::vector<int>& fitted) : model_(model), fitted_(fitted) {
    column_of_.assign(model.regions.size(), -1);
    for (std::size_t c = 0; c < fitted.size(); ++c) column_of_[static_cast<std::size_t>(fitted[c])] = static_cast<int>(c);
    const sim::Springs& sp = model.springs;
    for (int j = 0; j < sp.size(); ++j) {  // The springs a fitted region drives.
      const bool a = sp.region_a[j] >= 0 && column_of_[sp.region_a[j]] >= 0;
      const bool b = sp.region_b[j] >= 0 && column_of_[sp.region_b[j]] >= 0;
      if ((a || b) && sp.rest_m[j] > 0) rows_.push_back(j);
    }
    // Each region's contraction slots: its own, or with a conduction system the slots of its
    // spring ends (sim::Model::excited), each the region's drive from its own excitation.
    slots_of_.resize(model.regions.size());
    const auto count = [&](int region, int slot) {
      if (region < 0) return;
      auto& slots = slots_of_[static_cast<std::size_t>(region)];
      const auto it = std::find_if(slots.begin(), slots.end(), [&](const auto& e) { return e.first == slot; });
      if (it == slots.end()) slots.emplace_back(slot, 1.0); else it->second += 1.0;
    };
    for (int j = 0; j < sp.size(); ++j) {
      count(sp.region_a[j], sp.contraction_a.empty() ? sp.region_a[j] : sp.contraction_a[j]);
      count(sp.region_b[j], sp.contraction_b.empty() ? sp.region_b[j] : sp.contraction_b[j]);
    }
    for (auto& slots : slots_of_) {
      double ends = 0;
      for (const auto& e : slots) ends += e.second;
      for (auto& e : slots) e.second /= ends;
    }
    const auto columns = static_cast<Eigen::Index>(fitted.size());
    force_jacobian_.resize(3 * model.particle_count(), columns);
    length_jacobian_.resize(static_cast<Eigen::Index>(rows_.size()), columns);
    residual_.resize(static_cast<Eigen::Index>(rows_.size()));
  }

  /// Region r's contraction now: the mean over its spring ends' slots (its own without a
  /// conduction system).
  double now(const sim::State& state, std::size_t r) const {
    if (slots_of_[r].empty()) return state.region_contraction[static_cast<Eigen::Index>(r)];
    double c = 0;
    for (const auto& [slot, share] : slots_of_[r]) c += share * state.region_contraction[slot];
    return c;
  }

  /// Whether region r is fitted (has a column).
  bool fitted(std::size_t r) const { return column_of_[r] >= 0; }
  int column(std::size_t r) const { return column_of_[r]; }

  /// The change of each fitted region's contraction that lets the springs exert the
  /// attachments' force (coupling.h).
  Eigen::VectorXd from_forces(const sim::State& state, double h) {
    const sim::Springs& sp = model_.springs;
    force_jacobian_.setZero();
    for (int j = 0; j < sp.size(); ++j) {
      const int a = sp.a[j], b = sp.b[j];
      const Eigen::Vector3d d = state.x.col(b) - state.x.col(a);
      const double len = d.norm();
      if (len < 1e-12) continue;
      // The spring's force as one XPBD iteration exerts it, lambda / h^2 = -C / (h^2 w + alpha)
      // (XPBD eq. 18; the damper is a separate velocity pass): below the stiffness 1 / alpha
      // when the particles are light.
      const double k = 1.0 / (h * h * (model_.inverse_mass[a] + model_.inverse_mass[b]) + sp.compliance_m_per_N[j]);
      const Eigen::Vector3d gradient = (k * sp.rest_m[j] / len) * d;  // k L0 n
      for (int end : {sp.region_a[j], sp.region_b[j]}) {
        const int c = end >= 0 ? column_of_[end] : -1;
        if (c < 0) continue;
        // Contracting the spring pulls b towards a and a towards b (half per end region).
        if (model_.inverse_mass[b] > 0) force_jacobian_.block<3, 1>(3 * b, c) -= 0.5 * gradient;
        if (model_.inverse_mass[a] > 0) force_jacobian_.block<3, 1>(3 * a, c) += 0.5 * gradient;
      }
    }
    const Eigen::Matrix3Xd force = state.attachment_lambda / (h * h);
    return ridge_solve(force_jacobian_, Eigen::Map<const Eigen::VectorXd>(force.data(), force.size()), 1e-9);
  }

  /// The contractions whose driven rest lengths best match the springs' lengths now
  /// (coupling.h): two Gauss-Newton steps from the current contractions, derivatives by
  /// central differences of sim::driven_rest_length (fibres make it nonlinear in c). A
  /// region's change shifts all its slots alike; per region, its contraction now plus it.
  Eigen::VectorXd from_lengths(const sim::State& state) {
    const sim::Springs& sp = model_.springs;
    Eigen::VectorXd contraction = state.region_contraction;
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model_.regions.size()));
    constexpr double kDelta = 1e-4;
    // Spring j's driven rest length with `region`'s slots shifted by `by`: of them, only its
    // own ends' slots reach it, so only they are moved (and put back exactly).
    const auto shifted_rest = [&](int j, int region, double by) {
      const int ia = sp.contraction_a.empty() ? sp.region_a[j] : sp.contraction_a[j];
      const int ib = sp.contraction_b.empty() ? sp.region_b[j] : sp.contraction_b[j];
      const bool a = ia >= 0 && sp.region_a[j] == region, b = ib >= 0 && ib != ia && sp.region_b[j] == region;
      const double ca = a ? contraction[ia] : 0.0, cb = b ? contraction[ib] : 0.0;
      if (a) contraction[ia] += by;
      if (b) contraction[ib] += by;
      const double rest = sim::driven_rest_length(sp, j, contraction);
      if (a) contraction[ia] = ca;
      if (b) contraction[ib] = cb;
      return rest;
    };
    for (int iteration = 0; iteration < 2; ++iteration) {
      length_jacobian_.setZero();
      for (std::size_t i = 0; i < rows_.size(); ++i) {
        const int j = rows_[i];
        const auto row = static_cast<Eigen::Index>(i);
        const double length = (state.x.col(sp.b[j]) - state.x.col(sp.a[j])).norm();
        residual_[row] = (length - sim::driven_rest_length(sp, j, contraction)) / sp.rest_m[j];
        for (int end : {sp.region_a[j], sp.region_b[j]}) {
          if (end < 0 || column_of_[end] < 0 || length_jacobian_(row, column_of_[end]) != 0) continue;
          length_jacobian_(row, column_of_[end]) =
              (shifted_rest(j, end, kDelta) - shifted_rest(j, end, -kDelta)) / (2 * kDelta * sp.rest_m[j]);
        }
      }
      const Eigen::VectorXd step = ridge_solve(length_jacobian_, residual_, 1e-6);
      for (std::size_t c = 0; c < fitted_.size(); ++c) {
        const double by = step[static_cast<Eigen::Index>(c)];
        for (const auto& e : slots_of_[static_cast<std::size_t>(fitted_[c])]) contraction[e.first] += by;
        shift[fitted_[c]] += by;
      }
    }
    for (std::size_t r = 0; r < model_.regions.size(); ++r) shift[static_cast<Eigen::Index>(r)] += now(state, r);
    return shift;
  }

 private:
  const sim::Model& model_;
  const std::vector<int>& fitted_;
  std::vector<int> column_of_;  ///< Per region, its column, -1 when not fitted.
  std::vector<std::vector<std::pair<int, double>>> slots_of_;  ///< Per region: its slots, each with its share of the ends.
  std::vector<int> rows_;       ///< The springs a fitted region drives.
  Eigen::MatrixXd force_jacobian_, length_jacobian_;
  Eigen::VectorXd residual_;
};

/// The surface points the coupling ties to the target: the problem's embedding less the
/// valves' leaflets. A leaflet's place is the body's plus its valve's opening (world/valves.h),
/// which the measured surface adds; tied to where the target's leaflets swing, the embedded
/// point would drag the lattice cells around the valve ring open with it instead.
sim::Embedding coupled_points(const Problem& problem) {
  sim::Embedding points = problem.embedding;
  for (const world::ValveMotion::Leaflets& valve : problem.valves.valves) {
    for (const int v : valve.vertices) points.weight.col(v).setZero();
  }
  return points;
}

}  // namespace

RecordedSignals record_coupled(const Problem& problem, const sim::Model& base, double coupling_N_per_m,
                               const std::vector<int>& fitted) {
  const sim::Model model = sim::with_method(base, sim::Method::kXpbd);  // Attachments are XPBD constraints.
  const TargetMotion& target = problem.target;
  const double rate = problem.rate_hz;
  sim::Attachments coupling;
  coupling.target = [&target, rate](double t_s, Eigen::Matrix3Xd& out) { target.positions(rate * t_s, out); };
  coupling.compliance_m_per_N = 1.0 / coupling_N_per_m;
  const sim::Embedding points = coupled_points(problem);
  if (!points.empty()) coupling.points = &points;

  RecordedSignals rec;
  rec.contraction.assign(model.regions.size(), {});
  rec.length_contraction.assign(model.regions.size(), {});
  // The coupled body played alone; the recorder listens after every measured step.
  world::BodyPlayback playback(model, problem.dt_s, &coupling);
  const sim::State& state = playback.state();
  const int n = model.particle_count();
  SpringFits fits(model, fitted);
  const double h = problem.dt_s / model.substeps;
  double force_sum = 0;
  ErrorMeter floor(problem, ErrorMeter::Valves::kAsTheTarget);
  playback.run(problem.settle_steps, [&](int k) {
    if (k == problem.settle_steps - 1) floor.watch(state);
  });
  playback.run(problem.measure_steps, [&](int k) {
    floor.add(k, state);
    const Eigen::VectorXd dc = fits.from_forces(state, h);
    const Eigen::VectorXd by_length = fits.from_lengths(state);
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
      rec.contraction[r].push_back(fits.now(state, r) + (fits.fitted(r) ? dc[fits.column(r)] : 0.0));
      rec.length_contraction[r].push_back(by_length[static_cast<Eigen::Index>(r)]);
    }
    rec.times_s.push_back(state.time_s);
    force_sum += (state.attachment_lambda / (h * h)).colwise().norm().sum() / n;
  });
  rec.mean_coupling_force_N = force_sum / problem.measure_steps;
  rec.floor = floor.result(sim::diagnose(model, state).has_value());
  return rec;
}

}  // namespace systole::train
