#pragma once
// CMA-ES, the covariance matrix adaptation evolution strategy: Hansen's standard
// (mu/mu_w, lambda) form with cumulative step-size adaptation and rank-one plus rank-mu
// covariance updates, with the default constants of N. Hansen, "The CMA Evolution Strategy:
// A Tutorial" (arXiv:1604.00772, 2016), table 1. Minimizes over R^n; bounds are the
// caller's business (train/tune.cpp maps R^n into its box). Seeded: the same seed gives the
// same search. A generation's candidates are evaluated in parallel, each independently and
// collected by index, so the result does not depend on the thread count.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace systole::train {

struct CmaesSettings {
  double sigma = 0.1;          ///< Initial step size, in the search space's units.
  int max_evaluations = 300;   ///< Budget of objective evaluations.
  double tolerance_x = 1e-4;   ///< Stop when every coordinate's search spread is below this.
  double tolerance_f = 1e-9;   ///< Stop when the last generations' best values span less than this.
  std::uint64_t seed = 1;
  int threads = 1;             ///< Candidates evaluated at once.
};

struct CmaesGeneration {
  int generation = 0;
  int evaluations = 0;
  double best = 0;    ///< Best objective value so far.
  double sigma = 0;
};

struct CmaesResult {
  Eigen::VectorXd best_x;
  double best_f = 0;
  int generations = 0;
  int evaluations = 0;
  std::string stop_reason;
};

/// Minimizes f from `start`. f must be safe to call from several threads at once;
/// `progress` (optional) is called after every generation, on the calling thread.
CmaesResult minimize_cmaes(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& start,
                           const CmaesSettings& settings,
                           const std::function<void(const CmaesGeneration&)>& progress = nullptr);

}  // namespace systole::train
