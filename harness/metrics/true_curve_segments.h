// The true curves of a ground truth as one segment set: each dense polyline, the closing
// segment included for a closed curve, from end to end for an open one.
// In: a ground truth. Out: its curves' segments, curve after curve.
#pragma once

#include <vector>

#include "io/ground_truth_json.h"
#include "metrics/segments.h"

namespace curvebench {

std::vector<Segment2> true_curve_segments(const GroundTruth& truth);

}  // namespace curvebench
