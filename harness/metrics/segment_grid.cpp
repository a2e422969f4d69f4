#include "metrics/segment_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvebench {
namespace {

constexpr double kMaxCellsPerSide = 1024.0;

}  // namespace

SegmentGrid::SegmentGrid(std::span<const Segment2> segments) : segments_(segments), seen_(segments.size(), 0) {
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

double SegmentGrid::distance_to_nearest(Point2 p) const {
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

void SegmentGrid::segments_near(Point2 low, Point2 high, std::vector<int>& out) const {
  out.clear();
  if (high.x < min_.x || high.y < min_.y || low.x > max_.x || low.y > max_.y) return;
  if (++query_ == 0) {  // the stamps wrapped around: start them again
    std::fill(seen_.begin(), seen_.end(), 0);
    query_ = 1;
  }
  for (int c = column_of(low.x); c <= column_of(high.x); ++c) {
    for (int w = row_of(low.y); w <= row_of(high.y); ++w) {
      for (int index : cells_[static_cast<size_t>(w) * columns_ + c]) {
        if (seen_[index] == query_) continue;
        seen_[index] = query_;
        out.push_back(index);
      }
    }
  }
}

int SegmentGrid::column_of(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - min_.x) / cell_)), 0, columns_ - 1);
}

int SegmentGrid::row_of(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - min_.y) / cell_)), 0, rows_ - 1);
}

// Every cell the segment passes through: column by column, the rows its y-range there spans.
void SegmentGrid::insert(int index) {
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

}  // namespace curvebench
