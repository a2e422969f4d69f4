#include "core/distinct_points.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <numeric>

namespace curvebench {

DistinctPoints distinct_points(std::span<const Point2> points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  // Stable: among equal points the first occurrence comes first.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
  });
  std::vector<int> first_of(n);  // input index -> input index of its first occurrence
  for (int k = 0; k < n; ++k) {
    first_of[order[k]] = k > 0 && points[order[k]] == points[order[k - 1]] ? first_of[order[k - 1]] : order[k];
  }
  DistinctPoints distinct;
  distinct.point_of_input.resize(n);
  for (int i = 0; i < n; ++i) {
    if (first_of[i] == i) {
      distinct.point_of_input[i] = static_cast<int>(distinct.points.size());
      distinct.points.push_back(points[i]);
      distinct.input_of_point.push_back(i);
    } else {
      distinct.point_of_input[i] = distinct.point_of_input[first_of[i]];
    }
  }
  return distinct;
}

bool all_collinear(std::span<const Point2> points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const int n = static_cast<int>(points.size());
  auto P = [&](int i) { return Kernel::Point_2(points[i].x, points[i].y); };
  int second = 1;
  while (second < n && points[second] == points[0]) ++second;
  if (second >= n) return true;
  for (int i = second + 1; i < n; ++i) {
    if (CGAL::orientation(P(0), P(second), P(i)) != CGAL::COLLINEAR) return false;
  }
  return true;
}

}  // namespace curvebench
