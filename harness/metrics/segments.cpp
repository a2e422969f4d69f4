#include "metrics/segments.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace curvebench {

std::vector<Segment2> edge_segments(std::span<const Point2> points, std::span<const Edge> edges) {
  std::vector<Segment2> segments;
  segments.reserve(edges.size());
  const int count = static_cast<int>(points.size());
  for (const Edge& e : edges) {
    if (e[0] < 0 || e[1] < 0 || e[0] >= count || e[1] >= count) {
      throw std::out_of_range("edge [" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + "] names a point outside 0.." +
                              std::to_string(count - 1));
    }
    segments.push_back({points[e[0]], points[e[1]]});
  }
  return segments;
}

std::vector<Segment2> closed_polyline_segments(std::span<const Point2> polyline) {
  std::vector<Segment2> segments;
  segments.reserve(polyline.size());
  for (size_t i = 0; i < polyline.size(); ++i) segments.push_back({polyline[i], polyline[(i + 1) % polyline.size()]});
  return segments;
}

void require_finite(std::span<const Segment2> segments, const char* what) {
  for (const Segment2& s : segments) {
    if (!std::isfinite(s.source.x) || !std::isfinite(s.source.y) || !std::isfinite(s.target.x) || !std::isfinite(s.target.y)) {
      throw std::invalid_argument(std::string(what) + " has a non-finite coordinate");
    }
  }
}

}  // namespace curvebench
