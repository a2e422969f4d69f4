// Segments bucketed into a uniform grid of square cells, for nearest-segment and
// neighbourhood queries among many segments (the Hausdorff distance, the curve recall).
//
// In:  a non-empty set of finite segments (degenerate ones stand for points); the grid keeps
//      a view of it, which must outlive the grid.
// Out: distance_to_nearest(p): the exact Euclidean distance from p to the nearest segment;
//      segments_near(low, high, out): the indices, each once, of every segment that passes
//      through a cell meeting the box [low, high], a superset of the segments meeting the box.
// Each segment is listed in every cell it passes through. The cell side is about the mean
// spacing sqrt(area / count), never below extent / count nor extent / 1024 per side.
#pragma once

#include <span>
#include <vector>

#include "metrics/segments.h"

namespace curvebench {

class SegmentGrid {
 public:
  explicit SegmentGrid(std::span<const Segment2> segments);

  double distance_to_nearest(Point2 p) const;

  // Clears `out` first.
  void segments_near(Point2 low, Point2 high, std::vector<int>& out) const;

 private:
  int column_of(double x) const;
  int row_of(double y) const;
  void insert(int index);

  std::span<const Segment2> segments_;
  Point2 min_, max_;
  double cell_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
  std::vector<std::vector<int>> cells_;
  mutable std::vector<unsigned> seen_;  // per segment: the query that last listed it
  mutable unsigned query_ = 0;
};

}  // namespace curvebench
