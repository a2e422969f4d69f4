// The L2 error norm of Section 4 of the paper (after [PM15a]): the area of the symmetric
// difference between the true region and the reconstructed region, over the true area.
//
// In:  the true curves as segments (closed polylines; several curves and holes allowed)
//      and the reconstructed curve as segments (any edge set, closed or not).
// Out: the error, >= 0; 0 when the even-odd regions coincide. Both regions are even-odd
//      regions as defined in even_odd_areas.h, so an open polyline or a dangling edge
//      adds no area and the error is defined for every output; an empty reconstruction
//      has error 1. Throws std::invalid_argument if the true region has zero area. (Open
//      true curves bound no region: evaluate_reconstruction.h reports no number for them.)
#pragma once

#include <span>

#include "metrics/segments.h"

namespace curvebench {

double l2_error(std::span<const Segment2> true_curves, std::span<const Segment2> reconstruction);

}  // namespace curvebench
