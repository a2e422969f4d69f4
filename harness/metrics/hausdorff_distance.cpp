#include "metrics/hausdorff_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

namespace curvebench {
namespace {

// Segments bucketed into the square cells of their bounding box that they pass through.
class SegmentGrid {
 public:
  explicit SegmentGrid(std::span<const Segment2> segments) : segments_(segments) {
    min_ = max_ = segments.front().source;
    for (const Segment2& s : segments) {
      for (Point2 p : {s.source, s.target}) {
        min_ = {std::min(min_.x, p.x), std::min(min_.y, p.y)};
        max_ = {std::max(max_.x, p.x), std::max(max_.y, p.y)};
      }
    }
    const double width = max_.x - min_.x;
    const double height = max_.y - min_.y;
    const double extent = std::max(width, height);
    const double count = static_cast<double>(segments.size());
    cell_ = std::max({std::sqrt(width * height / count), extent / count, extent / kMaxCellsPerSide});
    if (!(cell_ > 0.0)) cell_ = 1.0;  // every segment is the same point
    columns_ = static_cast<int>(width / cell_) + 1;
    rows_ = static_cast<int>(height / cell_) + 1;
    cells_.resize(static_cast<size_t>(columns_) * rows_);
    for (int index = 0; index < static_cast<int>(segments.size()); ++index) insert(index);
  }

  double distance_to_nearest(Point2 p) const {
    const int column = column_of(p.x);
    const int row = row_of(p.y);
    double best = std::numeric_limits<double>::infinity();
    // A segment not met in rings 0..r lies in cells at least r full cells away from the
    // query point's cell; a point outside the grid is no nearer than its projection onto it.
    for (int r = 0; r <= std::max(columns_, rows_); ++r) {
      for (int c = column - r; c <= column + r; ++c) {
        if (c < 0 || c >= columns_) continue;
        const bool side_column = c == column - r || c == column + r;
        for (int w = row - r; w <= row + r; w += side_column ? 1 : 2 * std::max(r, 1)) {
          if (w < 0 || w >= rows_) continue;
          for (int index : cells_[static_cast<size_t>(w) * columns_ + c]) {
            best = std::min(best, distance_to_segment(p, segments_[index].source, segments_[index].target));
          }
        }
      }
      if (best <= r * cell_) break;
    }
    return best;
  }

 private:
  static constexpr double kMaxCellsPerSide = 1024.0;

  int column_of(double x) const { return std::clamp(static_cast<int>(std::floor((x - min_.x) / cell_)), 0, columns_ - 1); }
  int row_of(double y) const { return std::clamp(static_cast<int>(std::floor((y - min_.y) / cell_)), 0, rows_ - 1); }

  // Every cell the segment passes through: column by column, the rows its y-range there spans.
  void insert(int index) {
    const Segment2& s = segments_[index];
    const Point2 left = s.source.x <= s.target.x ? s.source : s.target;
    const Point2 right = s.source.x <= s.target.x ? s.target : s.source;
    const double dx = right.x - left.x;
    const int first_column = column_of(left.x);
    const int last_column = column_of(right.x);
    for (int c = first_column; c <= last_column; ++c) {
      double low_y = std::min(left.y, right.y);
      double high_y = std::max(left.y, right.y);
      if (dx > 0.0) {
        const double x0 = std::max(left.x, min_.x + c * cell_);
        const double x1 = std::min(right.x, min_.x + (c + 1) * cell_);
        const double y0 = left.y + (right.y - left.y) * ((x0 - left.x) / dx);
        const double y1 = left.y + (right.y - left.y) * ((x1 - left.x) / dx);
        low_y = std::min(y0, y1);
        high_y = std::max(y0, y1);
      }
      for (int w = row_of(low_y); w <= row_of(high_y); ++w) cells_[static_cast<size_t>(w) * columns_ + c].push_back(index);
    }
  }

  std::span<const Segment2> segments_;
  Point2 min_, max_;
  double cell_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
  std::vector<std::vector<int>> cells_;
};

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
