#include "stretchdenoise/bounded_least_squares.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace curvebench {
namespace {

// Where a value stands: free, held at a bound by the working set, or fixed for good (a zero
// extent, or a value the constraint needs at its bound because it cannot be met).
enum class Place : char { kFree, kAtLower, kAtUpper, kFixed };

}  // namespace

Eigen::VectorXd bounded_least_squares(const std::vector<Eigen::Triplet<double>>& h, std::span<const double> y,
                                      const Eigen::VectorXd& c, double b, const Eigen::VectorXd& lower,
                                      const Eigen::VectorXd& upper) {
  const int k = static_cast<int>(c.size());
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(y.size()), k);
  matrix.setFromTriplets(h.begin(), h.end());
  // |Hx - y|^2 / 2 = x^T G x / 2 + q^T x + const, G = H^T H plus the ridge.
  Eigen::SparseMatrix<double> gram = matrix.transpose() * matrix;
  double largest = 0;
  for (int j = 0; j < k; ++j) largest = std::max(largest, gram.coeff(j, j));
  Eigen::SparseMatrix<double> identity(k, k);
  identity.setIdentity();
  gram += (largest > 0 ? 1e-12 * largest : 1.0) * identity;
  const Eigen::VectorXd q =
      -(matrix.transpose() * Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size())));

  // A feasible start: zero (no move) within the bounds, then the values the constraint weighs
  // on most moved, one after another, as far towards c.x = b as their bounds allow.
  std::vector<Place> place(k, Place::kFree);
  Eigen::VectorXd x(k);
  std::vector<int> weighing;  // free values with c_j != 0, by decreasing |c_j|
  for (int j = 0; j < k; ++j) {
    if (!(lower[j] < upper[j])) {
      x[j] = 0.5 * (lower[j] + upper[j]);
      place[j] = Place::kFixed;
      continue;
    }
    x[j] = std::clamp(0.0, lower[j], upper[j]);
    if (c[j] != 0) weighing.push_back(j);
  }
  std::stable_sort(weighing.begin(), weighing.end(), [&](int i, int j) { return std::abs(c[i]) > std::abs(c[j]); });
  bool constrained = !weighing.empty();
  if (constrained) {
    double residual = b - c.dot(x), scale = std::abs(b);
    for (int j : weighing) {
      const double moved = std::clamp(x[j] + residual / c[j], lower[j], upper[j]);
      residual -= c[j] * (moved - x[j]);
      x[j] = moved;
    }
    for (int j = 0; j < k; ++j) scale += std::abs(c[j]) * std::max(std::abs(lower[j]), std::abs(upper[j]));
    if (std::abs(residual) > 1e-12 * scale) {
      // Out of reach: every value it weighs on went to its bound towards it, and stays there.
      for (int j : weighing) place[j] = Place::kFixed;
      constrained = false;
    }
  }

  std::vector<int> free, column_of(k, -1);
  std::vector<Eigen::Triplet<double>> entries;
  // Each iteration adds a bound to the working set or leaves the objective strictly lower, so
  // the method ends; the cap only guards against cycling on rounding (x stays feasible).
  for (int iteration = 0; iteration < 10 * k + 10; ++iteration) {
    free.clear();
    int free_weighing = 0;
    for (int j = 0; j < k; ++j) {
      if (place[j] != Place::kFree) continue;
      column_of[j] = static_cast<int>(free.size());
      free.push_back(j);
      free_weighing += c[j] != 0;
    }
    const int f = static_cast<int>(free.size());
    double multiplier = 0;  // of c.x = b at the working set's minimiser
    if (f > 0) {
      // The minimiser with the held values fixed: G_FF x_F = multiplier c_F - (q + G x_held)_F,
      // with c_F . x_F = b - c_held . x_held (a Schur step on the one constraint row).
      Eigen::VectorXd held = x;
      for (int j : free) held[j] = 0;
      const Eigen::VectorXd pull = gram * held + q;
      entries.clear();
      for (int column : free) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(gram, column); it; ++it) {
          if (place[it.row()] == Place::kFree) entries.emplace_back(column_of[it.row()], column_of[column], it.value());
        }
      }
      Eigen::SparseMatrix<double> block(f, f);
      block.setFromTriplets(entries.begin(), entries.end());
      const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(block);
      if (factor.info() != Eigen::Success) break;  // G is positive definite: only non-finite input
      Eigen::VectorXd pull_free(f), c_free(f);
      for (int i = 0; i < f; ++i) pull_free[i] = pull[free[i]], c_free[i] = c[free[i]];
      Eigen::VectorXd target = -factor.solve(pull_free);
      if (constrained) {
        const Eigen::VectorXd z = factor.solve(c_free);
        const double b_free = b - c.dot(held);
        multiplier = (b_free - c_free.dot(target)) / c_free.dot(z);
        target += multiplier * z;
      }
      // Towards it, up to the first bound in the way. The last free value the constraint weighs
      // on never blocks: the step keeps c.x, so it moves only by rounding, and holding it would
      // leave the constraint with no free value.
      double step = 1;
      int blocking = -1;
      Place blocked_at = Place::kFree;
      for (int i = 0; i < f; ++i) {
        const int j = free[i];
        if (constrained && c[j] != 0 && free_weighing == 1) continue;
        const double move = target[i] - x[j];
        if (target[i] < lower[j] && move < 0 && (lower[j] - x[j]) / move < step) {
          step = (lower[j] - x[j]) / move, blocking = j, blocked_at = Place::kAtLower;
        } else if (target[i] > upper[j] && move > 0 && (upper[j] - x[j]) / move < step) {
          step = (upper[j] - x[j]) / move, blocking = j, blocked_at = Place::kAtUpper;
        }
      }
      for (int i = 0; i < f; ++i) {
        const int j = free[i];
        x[j] = std::clamp(blocking < 0 ? target[i] : x[j] + step * (target[i] - x[j]), lower[j], upper[j]);
      }
      if (blocking >= 0) {
        x[blocking] = blocked_at == Place::kAtLower ? lower[blocking] : upper[blocking];
        place[blocking] = blocked_at;
        continue;
      }
    }
    // x minimises over the working set. A held value whose slope of the Lagrangian points into
    // its bounds (negative at a lower bound, positive at an upper one) is let go, the worst first.
    const Eigen::VectorXd gradient = gram * x + q;
    double scale = 0;
    for (int j = 0; j < k; ++j) scale = std::max(scale, std::abs(gradient[j]) + std::abs(multiplier * c[j]));
    double worst = 1e-9 * scale;
    int leaving = -1;
    for (int j = 0; j < k; ++j) {
      const double slope = gradient[j] - multiplier * c[j];
      const double wrong = place[j] == Place::kAtLower ? -slope : place[j] == Place::kAtUpper ? slope : 0.0;
      if (wrong > worst) worst = wrong, leaving = j;
    }
    if (leaving < 0) break;
    place[leaving] = Place::kFree;
  }
  return x;
}

}  // namespace curvebench
