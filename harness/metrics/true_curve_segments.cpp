#include "metrics/true_curve_segments.h"

namespace curvebench {

std::vector<Segment2> true_curve_segments(const GroundTruth& truth) {
  std::vector<Segment2> segments;
  for (const auto& curve : truth.curves) {
    const auto closed = closed_polyline_segments(curve.vertices);
    segments.insert(segments.end(), closed.begin(), closed.end());
  }
  return segments;
}

}  // namespace curvebench
