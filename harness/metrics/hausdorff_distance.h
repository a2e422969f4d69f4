// Symmetric Hausdorff distance between two segment sets (a true curve and a reconstruction,
// or a true and a reconstructed medial axis).
//
// In:  segment sets `a` and `b` (degenerate segments stand for points) and a tolerance.
// Out: the larger of the two directed distances: the farthest any point of `a` is from `b`,
//      and the farthest any point of `b` is from `a`, at most `tolerance` below the exact
//      value and never above it. Distances from a point to a set are exact Euclidean
//      distances to the nearest segment (found through a uniform grid). Along a segment of
//      length L whose ends are d0 and d1 from the other set, no point is farther than
//      (d0 + d1 + L) / 2 (distance to a set changes no faster than position), so segments
//      are bisected only while that bound exceeds the farthest distance found plus the
//      tolerance. Infinity if either set is empty. Throws std::invalid_argument if
//      tolerance <= 0 or a coordinate is not finite.
#pragma once

#include <span>

#include "metrics/segments.h"

namespace curvebench {

double hausdorff_distance(std::span<const Segment2> a, std::span<const Segment2> b, double tolerance);

}  // namespace curvebench
