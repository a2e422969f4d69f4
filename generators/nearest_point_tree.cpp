#include "generators/nearest_point_tree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace curvebench {
namespace {

double coordinate(Point2 p, int axis) { return axis == 0 ? p.x : p.y; }

double squared_distance_to_box(Point2 q, Point2 low, Point2 high) {
  const double dx = std::max({low.x - q.x, 0.0, q.x - high.x});
  const double dy = std::max({low.y - q.y, 0.0, q.y - high.y});
  return dx * dx + dy * dy;
}

}  // namespace

NearestPointTree::NearestPointTree(std::span<const Point2> points) : points_(points.begin(), points.end()), order_(points.size()), box_at_middle_(points.size()) {
  std::iota(order_.begin(), order_.end(), 0);
  // Build with an explicit work list of ranges; depth is only log n, but no recursion is needed.
  struct Range { int begin, end, axis; };
  std::vector<Range> work{{0, static_cast<int>(order_.size()), 0}};
  while (!work.empty()) {
    const Range r = work.back();
    work.pop_back();
    if (r.end - r.begin < 1) continue;
    const int middle = r.begin + (r.end - r.begin) / 2;
    Box box{points_[order_[r.begin]], points_[order_[r.begin]]};
    for (int i = r.begin + 1; i < r.end; ++i) {
      const Point2 p = points_[order_[i]];
      box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y)};
      box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y)};
    }
    box_at_middle_[middle] = box;
    std::nth_element(order_.begin() + r.begin, order_.begin() + middle, order_.begin() + r.end, [&](int a, int b) {
      const double ca = coordinate(points_[a], r.axis), cb = coordinate(points_[b], r.axis);
      return ca < cb || (ca == cb && a < b);
    });
    work.push_back({r.begin, middle, 1 - r.axis});
    work.push_back({middle + 1, r.end, 1 - r.axis});
  }
}

int NearestPointTree::nearest(Point2 query) const { return order_.empty() ? -1 : nearest(query, order_[0]); }

int NearestPointTree::nearest(Point2 query, int hint) const {
  int best = hint;
  double best_d2 = dot(points_[hint] - query, points_[hint] - query);
  // Depth-first with a stack of ranges, nearer side first, skipping boxes farther than the best.
  struct Range { int begin, end, axis; };
  Range stack[128];
  int top = 0;
  stack[top++] = {0, static_cast<int>(order_.size()), 0};
  while (top > 0) {
    const Range r = stack[--top];
    if (r.begin >= r.end) continue;
    const int middle = r.begin + (r.end - r.begin) / 2;
    const Box& box = box_at_middle_[middle];
    if (squared_distance_to_box(query, box.low, box.high) > best_d2) continue;
    const Point2 p = points_[order_[middle]];
    const double d2 = dot(p - query, p - query);
    if (d2 < best_d2 || (d2 == best_d2 && order_[middle] < best)) best_d2 = d2, best = order_[middle];
    const Range low{r.begin, middle, 1 - r.axis}, high{middle + 1, r.end, 1 - r.axis};
    // Pushed last is searched first.
    if (coordinate(query, r.axis) < coordinate(p, r.axis)) stack[top++] = high, stack[top++] = low;
    else stack[top++] = low, stack[top++] = high;
  }
  return best;
}

}  // namespace curvebench
