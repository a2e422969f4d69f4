// The output of a method that connects noisy samples and moves them onto a denoised curve:
// edges between the samples it was given, and one new position per sample.
#pragma once

#include <vector>

#include "core/point.h"

namespace curvebench {

struct DenoisedCurve {
  std::vector<Edge> edges;        // indices of the samples, make_edge order, sorted, each once
  std::vector<Point2> positions;  // positions[i]: where sample i moved (its own position if it did not)
};

}  // namespace curvebench
