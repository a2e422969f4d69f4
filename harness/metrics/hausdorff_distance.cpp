#include "metrics/hausdorff_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

#include "metrics/segment_grid.h"

namespace curvebench {
namespace {

// Best-first branch and bound over pieces of the segments of `from`, most promising first.
double directed_distance(std::span<const Segment2> from, const SegmentGrid& to, double tolerance) {
  struct Piece {
    Point2 source, target;
    double source_distance, target_distance;
    double bound() const { return 0.5 * (source_distance + target_distance + distance(source, target)); }
    bool operator<(const Piece& other) const { return bound() < other.bound(); }
  };
  std::priority_queue<Piece> pieces;
  double farthest = 0.0;
  for (const Segment2& s : from) {
    const Piece piece{s.source, s.target, to.distance_to_nearest(s.source), to.distance_to_nearest(s.target)};
    farthest = std::max({farthest, piece.source_distance, piece.target_distance});
    if (piece.bound() > farthest + tolerance) pieces.push(piece);
  }
  while (!pieces.empty() && pieces.top().bound() > farthest + tolerance) {
    const Piece piece = pieces.top();
    pieces.pop();
    const Point2 middle = 0.5 * (piece.source + piece.target);
    const double middle_distance = to.distance_to_nearest(middle);
    farthest = std::max(farthest, middle_distance);
    pieces.push({piece.source, middle, piece.source_distance, middle_distance});
    pieces.push({middle, piece.target, middle_distance, piece.target_distance});
  }
  return farthest;
}

}  // namespace

double hausdorff_distance(std::span<const Segment2> a, std::span<const Segment2> b, double tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("Hausdorff distance: the tolerance must be positive");
  require_finite(a, "Hausdorff distance: the first segment set");
  require_finite(b, "Hausdorff distance: the second segment set");
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  return std::max(directed_distance(a, SegmentGrid(b), tolerance), directed_distance(b, SegmentGrid(a), tolerance));
}

}  // namespace curvebench
