// The dominant-point measures of the paper's Section 4 (Table 1), taken over from the
// polygonal approximation of digital curves.
//
// In:  the input samples; for each sample the true curve it lies on (-1 for an outlier) and
//      its parameter along that curve (any increasing measure, e.g. arc-length fraction);
//      the indices of the samples reported as dominant points (duplicates count once).
// Out: count  the number of distinct dominant points;
//      CR     compression ratio = number of input samples / count (absent if count is 0);
//      ISE    integral square error: the sum, over every sample lying on a curve, of its
//             squared distance to the approximating polygon, in squared input units. The
//             curve points measured are the samples (as for a digital curve), not the dense
//             true curve. Each curve's polygon joins its dominant points in true curve
//             order, and a sample is measured against the polygon side whose two dominant
//             points enclose it along the curve (a dominant point itself scores 0; with a
//             single dominant point on a curve the side shrinks to that point). Absent if
//             some curve that carries samples has no dominant point, so no polygon.
//             Dominant points on outliers are counted but belong to no polygon;
//      FOM    figure of merit = CR / ISE (absent if either is absent or ISE is 0).
// Throws std::invalid_argument if the per-sample arrays and the samples differ in length or
// a dominant point is not a sample index.
#pragma once

#include <optional>
#include <span>

#include "core/point.h"

namespace curvebench {

struct DominantPointQuality {
  int count = 0;
  std::optional<double> compression_ratio;
  std::optional<double> integral_square_error;
  std::optional<double> figure_of_merit;
};

DominantPointQuality dominant_point_quality(std::span<const Point2> samples, std::span<const int> curve_of_sample,
                                            std::span<const double> parameter_of_sample,
                                            std::span<const int> dominant_points);

}  // namespace curvebench
