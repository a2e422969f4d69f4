#include "metrics/distance_to_curve.h"

#include <algorithm>
#include <vector>

#include "core/nearest_neighbors.h"

namespace curvebench {

DistanceToCurve distance_to_curve(std::span<const Segment2> curve, std::span<const Point2> points) {
  DistanceToCurve result;
  if (points.empty() || curve.empty()) return result;
  std::vector<Point2> midpoints;
  midpoints.reserve(curve.size());
  double half_longest = 0.0;
  for (const Segment2& s : curve) {
    midpoints.push_back(0.5 * (s.source + s.target));
    half_longest = std::max(half_longest, 0.5 * distance(s.source, s.target));
  }
  const NearestNeighbors index(midpoints);
  std::vector<int> near;
  double sum = 0.0;
  for (const Point2& p : points) {
    const Segment2& first = curve[index.nearest(p)];
    double best = distance_to_segment(p, first.source, first.target);
    // The point of a segment nearest to p lies within half the segment's length of its
    // midpoint, so every segment nearer than `best` has its midpoint within this radius.
    index.within_radius(p, best + half_longest, near);
    for (int k : near) best = std::min(best, distance_to_segment(p, curve[k].source, curve[k].target));
    sum += best;
    result.max = std::max(result.max, best);
  }
  result.mean = sum / static_cast<double>(points.size());
  return result;
}

}  // namespace curvebench
