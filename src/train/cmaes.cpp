#include "train/cmaes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

namespace systole::train {

CmaesResult minimize_cmaes(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& start,
                           const CmaesSettings& settings, const std::function<void(const CmaesGeneration&)>& progress) {
  const int n = static_cast<int>(start.size());
  CmaesResult result;
  result.best_x = start;
  result.best_f = f(start);
  result.evaluations = 1;
  if (n == 0 || settings.max_evaluations <= 1) {
    result.stop_reason = n == 0 ? "nothing to tune" : "budget";
    return result;
  }

  // Strategy parameters (Hansen 2016, table 1).
  const int lambda = 4 + static_cast<int>(std::floor(3.0 * std::log(double(n))));
  const int mu = lambda / 2;
  Eigen::VectorXd weights(mu);
  for (int i = 0; i < mu; ++i) weights[i] = std::log((lambda + 1) / 2.0) - std::log(double(i + 1));
  weights /= weights.sum();
  const double mu_eff = 1.0 / weights.squaredNorm();
  const double c_sigma = (mu_eff + 2) / (n + mu_eff + 5);
  const double d_sigma = 1 + 2 * std::max(0.0, std::sqrt((mu_eff - 1) / (n + 1)) - 1) + c_sigma;
  const double c_c = (4 + mu_eff / n) / (n + 4 + 2 * mu_eff / n);
  const double c_1 = 2 / ((n + 1.3) * (n + 1.3) + mu_eff);
  const double c_mu = std::min(1 - c_1, 2 * (mu_eff - 2 + 1 / mu_eff) / ((n + 2) * (n + 2) + mu_eff));
  const double chi_n = std::sqrt(double(n)) * (1 - 1.0 / (4 * n) + 1.0 / (21.0 * n * n));

  Eigen::VectorXd mean = start, p_sigma = Eigen::VectorXd::Zero(n), p_c = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd C = Eigen::MatrixXd::Identity(n, n), B = C;
  Eigen::VectorXd D = Eigen::VectorXd::Ones(n);
  double sigma = settings.sigma;
  std::mt19937_64 rng(settings.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> recent_best;

  while (true) {
    if (result.evaluations + lambda > settings.max_evaluations) {
      result.stop_reason = "budget";
      break;
    }
    // Draw every sample on this thread, in order: the search does not depend on threads.
    Eigen::MatrixXd z(n, lambda), y(n, lambda), x(n, lambda);
    for (int k = 0; k < lambda; ++k)
      for (int i = 0; i < n; ++i) z(i, k) = normal(rng);
    y = B * D.asDiagonal() * z;
    x = (sigma * y).colwise() + mean;
    std::vector<double> value(lambda);
#pragma omp parallel for num_threads(settings.threads) schedule(dynamic, 1) if (settings.threads > 1)
    for (int k = 0; k < lambda; ++k) value[k] = f(x.col(k));
    result.evaluations += lambda;
    ++result.generations;

    std::vector<int> order(lambda);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return value[a] < value[b]; });
    if (value[order[0]] < result.best_f) {
      result.best_f = value[order[0]];
      result.best_x = x.col(order[0]);
    }

    // Recombination and evolution paths.
    Eigen::VectorXd y_w = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < mu; ++i) y_w += weights[i] * y.col(order[i]);
    mean += sigma * y_w;
    const Eigen::VectorXd c_inv_sqrt_y = B * D.cwiseInverse().asDiagonal() * B.transpose() * y_w;
    p_sigma = (1 - c_sigma) * p_sigma + std::sqrt(c_sigma * (2 - c_sigma) * mu_eff) * c_inv_sqrt_y;
    const double ps_norm = p_sigma.norm();
    const bool h_sigma = ps_norm / std::sqrt(1 - std::pow(1 - c_sigma, 2.0 * result.generations)) < (1.4 + 2.0 / (n + 1)) * chi_n;
    p_c = (1 - c_c) * p_c + (h_sigma ? std::sqrt(c_c * (2 - c_c) * mu_eff) : 0.0) * y_w;

    // Covariance: rank-one (p_c) and rank-mu (the selected steps) updates.
    Eigen::MatrixXd rank_mu = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < mu; ++i) rank_mu += weights[i] * y.col(order[i]) * y.col(order[i]).transpose();
    const double delta_h = h_sigma ? 0.0 : c_c * (2 - c_c);
    C = (1 - c_1 - c_mu + c_1 * delta_h) * C + c_1 * p_c * p_c.transpose() + c_mu * rank_mu;
    sigma *= std::exp((c_sigma / d_sigma) * (ps_norm / chi_n - 1));

    C = 0.5 * (C + C.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
    B = eig.eigenvectors();
    D = eig.eigenvalues().cwiseMax(1e-20).cwiseSqrt();

    if (progress) progress({result.generations, result.evaluations, result.best_f, sigma});
    recent_best.push_back(value[order[0]]);
    const double spread = sigma * std::sqrt(C.diagonal().maxCoeff());
    if (spread < settings.tolerance_x) {
      result.stop_reason = "converged (search spread " + std::to_string(spread) + ")";
      break;
    }
    const std::size_t window = 10 + static_cast<std::size_t>(std::ceil(30.0 * n / lambda));
    if (recent_best.size() >= window) {
      const auto last = recent_best.end() - static_cast<std::ptrdiff_t>(window);
      const auto [lo, hi] = std::minmax_element(last, recent_best.end());
      if (*hi - *lo < settings.tolerance_f) {
        result.stop_reason = "converged (best value flat for " + std::to_string(window) + " generations)";
        break;
      }
    }
  }
  return result;
}

}  // namespace systole::train
