// Symmetric Hausdorff distance between two segment sets (a true curve and a reconstruction,
// or a true and a reconstructed medial axis).
//
// In:  segment sets `a` and `b` (degenerate segments stand for points) and a sampling step.
// Out: the larger of the two directed distances: the farthest any point of `a` is from `b`,
//      and the farthest any point of `b` is from `a`. Each set is walked at points at most
//      `step` apart along every segment, both ends included, and each such point's exact
//      Euclidean distance to the nearest segment of the other set is taken (found through a
//      uniform grid). Since distance to a set changes no faster than position, the result is
//      at most step/2 below the exact segment-to-segment Hausdorff distance, never above.
//      Infinity if either set is empty. Throws std::invalid_argument if step <= 0.
#pragma once

#include <span>

#include "metrics/segments.h"

namespace curvebench {

double hausdorff_distance(std::span<const Segment2> a, std::span<const Segment2> b, double step);

}  // namespace curvebench
