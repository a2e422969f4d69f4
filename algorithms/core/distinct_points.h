// The distinct points of an input, for algorithms that do not need the Delaunay layer.
//
// In:  points in any order, duplicates allowed.
// Out: each distinct point once, in order of first occurrence, with the input index of that
//      first occurrence and, for each input point, its distinct point; and whether the distinct points are all collinear (exact test).
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct DistinctPoints {
  std::vector<Point2> points;
  std::vector<int> input_of_point;  // points[k] == input[input_of_point[k]], its first occurrence
  std::vector<int> point_of_input;  // input index -> k with points[k] == input[i]
};

DistinctPoints distinct_points(std::span<const Point2> points);

// True if every point lies on one line (also for fewer than three points); exact predicates.
bool all_collinear(std::span<const Point2> points);

}  // namespace curvebench
