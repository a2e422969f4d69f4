// How far a reconstruction's vertices lie from the true curve: on noisy input, where edge
// exactness means little, this tells a method that moves its vertices onto the curve
// (denoising) from one that keeps them where the noise put them.
//
// In:  the true curves as segments; the points whose distance is wanted.
// Out: the mean and the largest Euclidean distance from a point to the nearest point of any
//      segment (exact up to rounding); both 0 for no points.
#pragma once

#include <span>

#include "core/point.h"
#include "metrics/segments.h"

namespace curvebench {

struct DistanceToCurve {
  double mean = 0.0;
  double max = 0.0;
};

DistanceToCurve distance_to_curve(std::span<const Segment2> curve, std::span<const Point2> points);

}  // namespace curvebench
