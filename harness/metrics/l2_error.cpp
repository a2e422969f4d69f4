#include "metrics/l2_error.h"

#include <stdexcept>

#include "metrics/even_odd_areas.h"

namespace curvebench {

double l2_error(std::span<const Segment2> true_curves, std::span<const Segment2> reconstruction) {
  const EvenOddAreas areas = even_odd_areas(true_curves, reconstruction);
  if (!(areas.first > 0.0)) throw std::invalid_argument("L2 error: the true curves enclose no area");
  return areas.symmetric_difference / areas.first;
}

}  // namespace curvebench
