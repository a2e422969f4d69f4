// The recall of a curve: how much of the true curve the reconstruction passes near.
//
// In:  the true curves as segments, the reconstructed curve as segments, and a tolerance
//      (a distance, > 0).
// Out: the share of the true curves' length that lies within `tolerance` of the
//      reconstruction (the length of the points of the true segments whose distance to the
//      nearest reconstructed segment is at most the tolerance, over the total length), in
//      [0, 1]; 0 when the reconstruction has no segment. Exact up to rounding: along a true
//      segment, the points within the tolerance of one reconstructed segment (a capsule, which
//      is convex) form one interval, and the covered length is the measure of the union of
//      those intervals. Reconstructed segments near a true one come from a uniform grid
//      (segment_grid.h), so the cost grows with the segments that are actually near.
// Unlike L2, which counts a region and so loses all of it to one gap, and Hausdorff, which
// reports the worst place only, a gap of length g costs about g - 2 tolerance of length
// (exactly that where the edges beside it are in line with it) and nothing more. Throws std::invalid_argument if the tolerance is not positive, a coordinate
// is not finite or the true curves have no length.
#pragma once

#include <span>

#include "metrics/segments.h"

namespace curvebench {

double curve_recall(std::span<const Segment2> true_curves, std::span<const Segment2> reconstruction, double tolerance);

}  // namespace curvebench
