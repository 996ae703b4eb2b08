// CMA-ES (train/cmaes.h) on functions whose minimum is known: it finds it, it is seeded, the
// thread count changes nothing, and it keeps to its budget.

#include "train/cmaes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <vector>

namespace systole::train {
namespace {

/// A sphere centred away from the start, scaled unevenly per axis (an ill-conditioned
/// ellipsoid, condition 100): minimum 0 at `centre`.
struct ShiftedEllipsoid {
  Eigen::VectorXd centre;
  double operator()(const Eigen::VectorXd& x) const {
    double f = 0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double scale = std::pow(100.0, double(i) / double(std::max<Eigen::Index>(1, x.size() - 1)));
      f += scale * (x[i] - centre[i]) * (x[i] - centre[i]);
    }
    return f;
  }
};

Eigen::VectorXd centre(int n) {
  Eigen::VectorXd c(n);
  for (int i = 0; i < n; ++i) c[i] = 0.3 - 0.17 * i;
  return c;
}

CmaesSettings settings(std::uint64_t seed) {
  CmaesSettings s;
  s.sigma = 0.3;
  s.max_evaluations = 3000;
  s.tolerance_x = 1e-6;
  s.tolerance_f = 1e-14;
  s.seed = seed;
  return s;
}

TEST(Cmaes, FindsTheMinimumOfAShiftedEllipsoid) {
  const int n = 5;
  const ShiftedEllipsoid f{centre(n)};
  const CmaesResult r = minimize_cmaes(f, Eigen::VectorXd::Zero(n), settings(3));
  EXPECT_LT((r.best_x - centre(n)).norm(), 1e-4) << r.stop_reason;
  EXPECT_LT(r.best_f, 1e-8);
  EXPECT_NEAR(f(r.best_x), r.best_f, 1e-15);  // The reported value is the point's.
  EXPECT_NE(r.stop_reason.find("converged"), std::string::npos) << r.stop_reason;
  EXPECT_LE(r.evaluations, 3000);
}

TEST(Cmaes, FindsTheRosenbrockValleysMinimum) {
  // Rosenbrock's banana, minimum 0 at (1, 1): a curved valley that a search without an
  // adapted covariance crawls along.
  const auto rosenbrock = [](const Eigen::VectorXd& x) {
    return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
  };
  CmaesSettings s = settings(11);
  s.sigma = 0.5;
  const CmaesResult r = minimize_cmaes(rosenbrock, Eigen::Vector2d(-1.2, 1.0), s);
  EXPECT_LT((r.best_x - Eigen::Vector2d(1, 1)).norm(), 1e-3) << r.stop_reason;
  EXPECT_LT(r.best_f, 1e-6);
}

TEST(Cmaes, TheSameSeedGivesTheSameSearch) {
  const int n = 4;
  const ShiftedEllipsoid f{centre(n)};
  CmaesSettings s = settings(42);
  s.max_evaluations = 200;  // Stopped mid-search, where any difference would still show.
  const CmaesResult a = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  const CmaesResult b = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  EXPECT_EQ(a.best_x, b.best_x);
  EXPECT_EQ(a.best_f, b.best_f);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.generations, b.generations);
  s.seed = 43;
  const CmaesResult c = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  EXPECT_NE(a.best_x, c.best_x);  // Another seed draws other candidates.
}

TEST(Cmaes, TheThreadCountChangesNothing) {
  const int n = 6;
  const ShiftedEllipsoid f{centre(n)};
  CmaesSettings s = settings(5);
  s.max_evaluations = 400;
  const CmaesResult one = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  s.threads = 3;
  const CmaesResult three = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  EXPECT_EQ(one.best_x, three.best_x);
  EXPECT_EQ(one.best_f, three.best_f);
  EXPECT_EQ(one.evaluations, three.evaluations);
}

TEST(Cmaes, KeepsToItsBudgetAndCountsEveryEvaluation) {
  const int n = 3;
  std::atomic<int> calls{0};
  const ShiftedEllipsoid ellipsoid{centre(n)};
  const auto f = [&](const Eigen::VectorXd& x) {
    ++calls;
    return ellipsoid(x);
  };
  CmaesSettings s = settings(9);
  s.max_evaluations = 50;
  s.threads = 2;
  const CmaesResult r = minimize_cmaes(f, Eigen::VectorXd::Zero(n), s);
  EXPECT_EQ(r.stop_reason, "budget");
  EXPECT_LE(r.evaluations, 50);
  EXPECT_EQ(r.evaluations, calls.load());
  // Lambda = 4 + floor(3 ln 3) = 7 candidates a generation, the start evaluated once.
  EXPECT_EQ(r.evaluations, 1 + 7 * r.generations);
  EXPECT_GT(r.evaluations, 50 - 7);  // It used the budget it had.
}

TEST(Cmaes, ProgressReportsEveryGenerationWithABestThatNeverWorsens) {
  const int n = 3;
  const ShiftedEllipsoid f{centre(n)};
  std::vector<CmaesGeneration> seen;
  const CmaesResult r = minimize_cmaes(f, Eigen::VectorXd::Zero(n), settings(2),
                                       [&](const CmaesGeneration& g) { seen.push_back(g); });
  ASSERT_EQ(static_cast<int>(seen.size()), r.generations);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].generation, static_cast<int>(i) + 1);
    EXPECT_GT(seen[i].sigma, 0.0);
    if (i > 0) {
      EXPECT_LE(seen[i].best, seen[i - 1].best);
      EXPECT_GT(seen[i].evaluations, seen[i - 1].evaluations);
    }
  }
  EXPECT_EQ(seen.back().best, r.best_f);
  EXPECT_EQ(seen.back().evaluations, r.evaluations);
  // The best never rises above the start's value: the start is a candidate too.
  EXPECT_LE(seen.front().best, f(Eigen::VectorXd::Zero(n)));
}

TEST(Cmaes, AStartAtTheMinimumStaysThere) {
  const int n = 3;
  const ShiftedEllipsoid f{centre(n)};
  const CmaesResult r = minimize_cmaes(f, centre(n), settings(4));
  EXPECT_EQ(r.best_f, 0.0);
  EXPECT_EQ(r.best_x, centre(n));
}

TEST(Cmaes, NothingToSearchReturnsTheStart) {
  const CmaesResult r = minimize_cmaes([](const Eigen::VectorXd&) { return 7.0; }, Eigen::VectorXd(), settings(1));
  EXPECT_EQ(r.best_f, 7.0);
  EXPECT_EQ(r.evaluations, 1);
  EXPECT_EQ(r.generations, 0);
}

}  // namespace
}  // namespace systole::train
