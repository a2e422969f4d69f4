// The output of a method that connects noisy samples and moves them onto a denoised curve:
// edges between the samples it was given, and one new position per sample.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct DenoisedCurve {
  std::vector<Edge> edges;        // indices of the samples, make_edge order, sorted, each once
  std::vector<Point2> positions;  // positions[i]: where sample i moved (its own position if it did not)
};

// A moved position that is not finite (with coordinates so large that their squares
// overflow, a fit or a solve can divide infinity by infinity) is no position: the sample
// keeps its own instead, so that a denoiser never reports NaN as a vertex.
inline void keep_finite_positions(std::span<const Point2> samples, std::vector<Point2>& positions) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y)) positions[i] = samples[i];
  }
}

}  // namespace curvebench
