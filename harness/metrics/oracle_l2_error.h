// The "oracle" L2 error: the L2 error (l2_error.h) of the polygons that join the samples in
// their true order along each curve, i.e. of the true adjacency edges. It is what a perfect
// interpolating reconstruction scores, so it shows how much of an algorithm's error the
// sampling itself causes (chords cutting curved arcs, noise, missing curves without samples).
//
// In:  the ground truth and the input points it describes (one per truth sample).
// Out: the error, >= 0; NaN (written as null) when a true curve is open, since an open
//      curve bounds no region. Throws std::invalid_argument if the point count differs from
//      the truth's sample count or the true curves enclose no area.
#pragma once

#include <span>

#include "io/ground_truth_json.h"

namespace curvebench {

double oracle_l2_error(const GroundTruth& truth, std::span<const Point2> points);

}  // namespace curvebench
