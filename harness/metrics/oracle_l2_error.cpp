#include "metrics/oracle_l2_error.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "metrics/l2_error.h"
#include "metrics/true_curve_segments.h"

namespace curvebench {

double oracle_l2_error(const GroundTruth& truth, std::span<const Point2> points) {
  if (points.size() != truth.samples.size()) {
    throw std::invalid_argument("the points file has " + std::to_string(points.size()) + " points but the ground truth describes " +
                                std::to_string(truth.samples.size()) + " samples");
  }
  if (has_open_curve(truth.curves)) return std::numeric_limits<double>::quiet_NaN();
  return l2_error(true_curve_segments(truth), edge_segments(points, truth.edges));
}

}  // namespace curvebench
