// bounded_least_squares (algorithms/stretchdenoise/bounded_least_squares.h) against the
// definition of its optimum: a convex problem's minimiser is the minimiser of the equality
// problem on some set of bounds held, so trying every set of held bounds and keeping the best
// feasible result finds it.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "stretchdenoise/bounded_least_squares.h"

namespace curvebench {
namespace {

struct Problem {
  std::vector<Eigen::Triplet<double>> h;
  std::vector<double> y;
  Eigen::VectorXd c, lower, upper;
  double b = 0;
  Eigen::MatrixXd dense() const {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(y.size()), c.size());
    for (const auto& e : h) m(e.row(), e.col()) += e.value();
    return m;
  }
};

// Rows shaped like a window's angle rows (row i weighs on columns i - 2, i - 1 and i), with
// two more rows than unknowns; some constraint weights are zero.
Problem random_problem(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), extent(0.05, 1.0);
  Problem p;
  for (int row = 0; row < k + 2; ++row) {
    for (int column = row - 2; column <= row; ++column) {
      if (column >= 0 && column < k) p.h.emplace_back(row, column, unit(rng));
    }
    p.y.push_back(2 * unit(rng));
  }
  p.c.resize(k);
  p.lower.resize(k);
  p.upper.resize(k);
  for (int j = 0; j < k; ++j) {
    p.c[j] = unit(rng) < -0.6 ? 0.0 : unit(rng);
    p.lower[j] = -extent(rng);
    p.upper[j] = extent(rng);
  }
  p.b = unit(rng);
  return p;
}

double objective(const Problem& p, const Eigen::VectorXd& x) {
  return (p.dense() * x - Eigen::Map<const Eigen::VectorXd>(p.y.data(), p.y.size())).squaredNorm();
}

// The least-squares minimiser (with the function's ridge) with the values `held` (0 free,
// -1 at lower, +1 at upper) and, if `with_constraint`, c.x = b; nullopt where that system
// is singular.
std::optional<Eigen::VectorXd> equality_minimiser(const Problem& p, const std::vector<int>& held, bool with_constraint) {
  const Eigen::MatrixXd h = p.dense();
  const int k = static_cast<int>(p.c.size());
  Eigen::MatrixXd gram = h.transpose() * h;
  const double largest = gram.diagonal().maxCoeff();
  gram += (largest > 0 ? 1e-12 * largest : 1.0) * Eigen::MatrixXd::Identity(k, k);
  const Eigen::VectorXd rhs = h.transpose() * Eigen::Map<const Eigen::VectorXd>(p.y.data(), p.y.size());
  // KKT system over x and the constraint's multiplier; held values are rows x_j = bound.
  const int size = k + (with_constraint ? 1 : 0);
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd right = Eigen::VectorXd::Zero(size);
  for (int j = 0; j < k; ++j) {
    if (held[j] != 0) {
      kkt(j, j) = 1;
      right[j] = held[j] < 0 ? p.lower[j] : p.upper[j];
      continue;
    }
    kkt.row(j).head(k) = gram.row(j);
    right[j] = rhs[j];
    if (with_constraint) kkt(j, k) = -p.c[j];
  }
  if (with_constraint) {
    kkt.row(k).head(k) = p.c.transpose();
    right[k] = p.b;
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
  if (!lu.isInvertible()) return std::nullopt;
  return Eigen::VectorXd(lu.solve(right).head(k));
}

bool within_bounds(const Problem& p, const Eigen::VectorXd& x, double slack) {
  for (int j = 0; j < x.size(); ++j) {
    if (x[j] < p.lower[j] - slack || x[j] > p.upper[j] + slack) return false;
  }
  return true;
}

// The best feasible equality minimiser over every set of held bounds.
std::optional<Eigen::VectorXd> brute_force_optimum(const Problem& p, bool with_constraint) {
  const int k = static_cast<int>(p.c.size());
  std::optional<Eigen::VectorXd> best;
  std::vector<int> held(k, 0);
  int combinations = 1;
  for (int j = 0; j < k; ++j) combinations *= 3;
  for (int code = 0; code < combinations; ++code) {
    for (int j = 0, rest = code; j < k; ++j, rest /= 3) held[j] = rest % 3 - 1;
    const std::optional<Eigen::VectorXd> x = equality_minimiser(p, held, with_constraint);
    if (!x || !within_bounds(p, *x, 1e-12)) continue;
    if (with_constraint && std::abs(p.c.dot(*x) - p.b) > 1e-9) continue;
    if (!best || objective(p, *x) < objective(p, *best)) best = x;
  }
  return best;
}

// The reach of c.x within the bounds.
std::pair<double, double> reach(const Problem& p) {
  double low = 0, high = 0;
  for (int j = 0; j < p.c.size(); ++j) {
    low += std::min(p.c[j] * p.lower[j], p.c[j] * p.upper[j]);
    high += std::max(p.c[j] * p.lower[j], p.c[j] * p.upper[j]);
  }
  return {low, high};
}

TEST(BoundedLeastSquares, FindsTheOptimumOverEverySetOfHeldBounds) {
  std::mt19937 rng(11);
  int held_at_optimum = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = 1 + trial % 6;
    Problem p = random_problem(rng, k);
    const auto [low, high] = reach(p);
    if (p.b < low || p.b > high) p.b = 0.5 * (low + high);  // reachable here; the next test has the rest
    const Eigen::VectorXd x = bounded_least_squares(p.h, p.y, p.c, p.b, p.lower, p.upper);
    const std::optional<Eigen::VectorXd> best = brute_force_optimum(p, p.c.cwiseAbs().maxCoeff() > 0);
    ASSERT_TRUE(best.has_value()) << trial;
    EXPECT_TRUE(within_bounds(p, x, 0)) << trial;
    if (p.c.cwiseAbs().maxCoeff() > 0) {
      EXPECT_NEAR(p.c.dot(x), p.b, 1e-9) << trial;
    }
    EXPECT_LE(objective(p, x), objective(p, *best) + 1e-9 * (1 + objective(p, *best))) << trial;
    EXPECT_LT((x - *best).cwiseAbs().maxCoeff(), 1e-6) << trial;
    for (int j = 0; j < k; ++j) held_at_optimum += x[j] == p.lower[j] || x[j] == p.upper[j];
  }
  EXPECT_GT(held_at_optimum, 200);  // the bounds matter on many of these problems
}

TEST(BoundedLeastSquares, AnUnreachableConstraintHoldsItsValuesAtTheNearestBounds) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int k = 2 + trial % 5;
    Problem p = random_problem(rng, k);
    const auto [low, high] = reach(p);
    if (high - low == 0) continue;
    const bool above = trial % 2 == 0;
    p.b = above ? high + 0.5 : low - 0.5;
    const Eigen::VectorXd x = bounded_least_squares(p.h, p.y, p.c, p.b, p.lower, p.upper);
    EXPECT_TRUE(within_bounds(p, x, 0)) << trial;
    EXPECT_NEAR(p.c.dot(x), above ? high : low, 1e-12) << trial;
    // The values the constraint does not weigh on minimise the objective within their bounds.
    Problem rest = p;
    for (int j = 0; j < k; ++j) {
      if (p.c[j] != 0) rest.lower[j] = rest.upper[j] = x[j];
    }
    rest.c.setZero();
    const std::optional<Eigen::VectorXd> best = brute_force_optimum(rest, false);
    ASSERT_TRUE(best.has_value()) << trial;
    EXPECT_LT((x - *best).cwiseAbs().maxCoeff(), 1e-6) << trial;
  }
}

TEST(BoundedLeastSquares, ZeroExtentsAndAZeroConstraintRowAreHandled) {
  std::mt19937 rng(2);
  Problem p = random_problem(rng, 5);
  p.lower[1] = p.upper[1] = 0.25;  // a chain end: extent 0
  p.c.setZero();                   // no sample weighs on the window
  const Eigen::VectorXd x = bounded_least_squares(p.h, p.y, p.c, 3.0, p.lower, p.upper);
  EXPECT_EQ(x[1], 0.25);
  const std::optional<Eigen::VectorXd> best = brute_force_optimum(p, false);
  ASSERT_TRUE(best.has_value());
  EXPECT_LT((x - *best).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(BoundedLeastSquares, AWindowWithoutAngleRowsMovesAsLittleAsTheConstraintAllows) {
  // Collinear vertices: H is zero, and the ridge picks the smallest move meeting c.x = b.
  const Eigen::VectorXd c = Eigen::Vector3d(1.0, 2.0, 1.0);
  const Eigen::VectorXd lower = Eigen::Vector3d::Constant(-1.0), upper = Eigen::Vector3d::Constant(1.0);
  const Eigen::VectorXd x = bounded_least_squares({}, std::vector<double>{0.0, 0.0}, c, 1.2, lower, upper);
  // The least-norm point of c.x = 1.2 is c * 1.2 / |c|^2 = (0.2, 0.4, 0.2).
  EXPECT_NEAR(x[0], 0.2, 1e-9);
  EXPECT_NEAR(x[1], 0.4, 1e-9);
  EXPECT_NEAR(x[2], 0.2, 1e-9);
}

}  // namespace
}  // namespace curvebench
