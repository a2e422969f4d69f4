// The least-squares problem of one StretchDenoise window (specification.md 2.9), solved to
// its optimum: minimise |H x - y|^2 subject to c.x = b and lower <= x <= upper.
//
// The reference clamps every value outside its bounds, freezes it there and re-solves the
// rest; the specification lists that among the flaws not to copy (§3): a value frozen at a
// bound never comes back, so the result can be far from the optimum and even further from
// the curve than the samples. Here a primal active-set method (Nocedal and Wright, Numerical
// Optimization, Algorithm 16.3) moves bounds in and out of the working set until the KKT
// conditions hold: each step solves the equality-constrained problem on the free values with
// a sparse LDL^T of their block of H^T H (Eigen) and a Schur step for c.x = b.
//
// In:  H as triplets (row, column < k, value) over y.size() rows; y; c, lower and upper of
//      size k, with lower <= upper; b.
// Out: the minimiser x (size k). A ridge of 1e-12 of H^T H's largest diagonal entry (1 where
//      H is zero) makes it unique: a window whose angle rows vanish (collinear vertices) gets
//      the smallest move. Where no x within the bounds meets c.x = b, every x_j with c_j != 0
//      is at the bound that brings c.x nearest to b, and the others minimise |H x - y|^2
//      within their bounds. A zero c leaves the bounded least-squares problem.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <span>
#include <vector>

namespace curvebench {

Eigen::VectorXd bounded_least_squares(const std::vector<Eigen::Triplet<double>>& h, std::span<const double> y,
                                      const Eigen::VectorXd& c, double b, const Eigen::VectorXd& lower,
                                      const Eigen::VectorXd& upper);

}  // namespace curvebench
