#include "metrics/true_curve_segments.h"

namespace curvebench {

std::vector<Segment2> true_curve_segments(const GroundTruth& truth) {
  std::vector<Segment2> segments;
  for (const auto& curve : truth.curves) {
    auto pieces = closed_polyline_segments(curve.vertices);
    if (!curve.closed && !pieces.empty()) pieces.pop_back();  // no segment from the last vertex back to the first
    segments.insert(segments.end(), pieces.begin(), pieces.end());
  }
  return segments;
}

}  // namespace curvebench
