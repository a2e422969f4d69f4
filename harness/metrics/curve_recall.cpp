#include "metrics/curve_recall.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "metrics/segment_grid.h"

namespace curvebench {
namespace {

struct Interval {
  double low, high;
  bool empty() const { return !(low <= high); }
};

// Parameters t where |a + t d - centre| <= radius.
Interval disk_interval(Point2 a, Point2 d, Point2 centre, double radius) {
  const Point2 offset = a - centre;
  const double qa = dot(d, d), qb = dot(d, offset), qc = dot(offset, offset) - radius * radius;
  const double discriminant = qb * qb - qa * qc;
  if (discriminant < 0.0) return {1.0, 0.0};
  const double root = std::sqrt(discriminant);
  return {(-qb - root) / qa, (-qb + root) / qa};
}

// Narrows `interval` to the parameters t where low <= value0 + t slope <= high.
void clip_linear(Interval& interval, double value0, double slope, double low, double high) {
  if (slope == 0.0) {
    if (value0 < low || value0 > high) interval = {1.0, 0.0};
    return;
  }
  double t0 = (low - value0) / slope, t1 = (high - value0) / slope;
  if (t0 > t1) std::swap(t0, t1);
  interval.low = std::max(interval.low, t0);
  interval.high = std::min(interval.high, t1);
}

// Parameters t in [0, 1] where a + t d lies within `radius` of segment s: the capsule around
// s is the union of the disks at its ends and the rectangle along it, and is convex, so the
// union of the three intervals is one interval.
Interval capsule_interval(Point2 a, Point2 d, const Segment2& s, double radius) {
  Interval covered{1.0, 0.0};
  auto join = [&covered](Interval piece) {
    if (piece.empty()) return;
    covered = covered.empty() ? piece : Interval{std::min(covered.low, piece.low), std::max(covered.high, piece.high)};
  };
  join(disk_interval(a, d, s.source, radius));
  join(disk_interval(a, d, s.target, radius));
  const double length = distance(s.source, s.target);
  if (length > 0.0) {
    const Point2 along = (1.0 / length) * (s.target - s.source);
    const Point2 offset = a - s.source;
    Interval rectangle{-INFINITY, INFINITY};
    clip_linear(rectangle, dot(offset, along), dot(d, along), 0.0, length);
    clip_linear(rectangle, cross(along, offset), cross(along, d), -radius, radius);
    join(rectangle);
  }
  covered.low = std::max(covered.low, 0.0);
  covered.high = std::min(covered.high, 1.0);
  return covered;
}

}  // namespace

double curve_recall(std::span<const Segment2> true_curves, std::span<const Segment2> reconstruction, double tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("curve recall: the tolerance must be positive");
  require_finite(true_curves, "curve recall: the true curves");
  require_finite(reconstruction, "curve recall: the reconstruction");
  double total = 0.0;
  for (const Segment2& s : true_curves) total += distance(s.source, s.target);
  if (!(total > 0.0)) throw std::invalid_argument("curve recall: the true curves have no length");
  if (reconstruction.empty()) return 0.0;

  const SegmentGrid grid(reconstruction);
  std::vector<int> near;
  std::vector<Interval> pieces;
  double covered = 0.0;
  for (const Segment2& s : true_curves) {
    const double length = distance(s.source, s.target);
    if (length == 0.0) continue;
    const Point2 low{std::min(s.source.x, s.target.x) - tolerance, std::min(s.source.y, s.target.y) - tolerance};
    const Point2 high{std::max(s.source.x, s.target.x) + tolerance, std::max(s.source.y, s.target.y) + tolerance};
    grid.segments_near(low, high, near);
    pieces.clear();
    const Point2 direction = s.target - s.source;
    for (int index : near) {
      const Interval piece = capsule_interval(s.source, direction, reconstruction[index], tolerance);
      if (!piece.empty()) pieces.push_back(piece);
    }
    std::sort(pieces.begin(), pieces.end(), [](const Interval& a, const Interval& b) { return a.low < b.low; });
    double measure = 0.0, reached = 0.0;
    for (const Interval& piece : pieces) {
      const double from = std::max(piece.low, reached);
      if (piece.high > from) measure += piece.high - from;
      reached = std::max(reached, piece.high);
    }
    covered += measure * length;
  }
  return std::min(covered / total, 1.0);
}

}  // namespace curvebench
