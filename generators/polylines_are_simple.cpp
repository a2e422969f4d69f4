#include "generators/polylines_are_simple.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace curvebench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_2;

struct Segment {
  int curve;
  int edge;
  KPoint a, b;
  double min_x, min_y, max_x, max_y;
};

bool between(const KPoint& p, const KPoint& q, const KPoint& r) {  // r on the closed box of pq
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
         r.y() <= std::max(p.y(), q.y());
}

// Closed segments intersect (exact: orientations are exact, coordinate comparisons too).
bool segments_meet(const Segment& s, const Segment& t) {
  const auto o1 = CGAL::orientation(s.a, s.b, t.a), o2 = CGAL::orientation(s.a, s.b, t.b);
  const auto o3 = CGAL::orientation(t.a, t.b, s.a), o4 = CGAL::orientation(t.a, t.b, s.b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == CGAL::COLLINEAR && between(s.a, s.b, t.a)) || (o2 == CGAL::COLLINEAR && between(s.a, s.b, t.b)) ||
         (o3 == CGAL::COLLINEAR && between(t.a, t.b, s.a)) || (o4 == CGAL::COLLINEAR && between(t.a, t.b, s.b));
}

// Consecutive edges a-b, b-c share b; they meet elsewhere only if c folds back over a-b.
bool consecutive_edges_fold(const KPoint& a, const KPoint& b, const KPoint& c) {
  return CGAL::orientation(a, b, c) == CGAL::COLLINEAR && (c.x() - b.x()) * (a.x() - b.x()) + (c.y() - b.y()) * (a.y() - b.y()) > 0;
}

}  // namespace

std::string find_polyline_crossing(const std::vector<std::vector<Point2>>& polylines, const std::vector<bool>& closed) {
  auto is_closed = [&](int c) { return closed.empty() || closed[c]; };
  std::vector<Segment> segments;
  double min_x = HUGE_VAL, min_y = HUGE_VAL, max_x = -HUGE_VAL, max_y = -HUGE_VAL;
  for (int c = 0; c < static_cast<int>(polylines.size()); ++c) {
    const auto& poly = polylines[c];
    const int n = static_cast<int>(poly.size());
    const int edges = is_closed(c) ? n : n - 1;
    for (int i = 0; i < n; ++i) {
      if (i == edges) {  // the last vertex of an open polyline starts no edge
        min_x = std::min(min_x, poly[i].x), min_y = std::min(min_y, poly[i].y);
        max_x = std::max(max_x, poly[i].x), max_y = std::max(max_y, poly[i].y);
        continue;
      }
      const Point2 p = poly[i], q = poly[(i + 1) % n];
      if (p == q) return "curve " + std::to_string(c) + " repeats vertex " + std::to_string(i);
      segments.push_back({c, i, KPoint(p.x, p.y), KPoint(q.x, q.y), std::min(p.x, q.x), std::min(p.y, q.y),
                          std::max(p.x, q.x), std::max(p.y, q.y)});
      min_x = std::min(min_x, p.x), min_y = std::min(min_y, p.y), max_x = std::max(max_x, p.x), max_y = std::max(max_y, p.y);
    }
    for (int i = 0; i + (is_closed(c) ? 0 : 2) < n; ++i) {
      const Point2 a = poly[i], b = poly[(i + 1) % n], c2 = poly[(i + 2) % n];
      if (n >= 3 && consecutive_edges_fold(KPoint(a.x, a.y), KPoint(b.x, b.y), KPoint(c2.x, c2.y))) {
        return "curve " + std::to_string(c) + " folds back at vertex " + std::to_string((i + 1) % n);
      }
    }
  }
  if (segments.empty()) return "";

  // Bucket edges by the grid cells their bounding boxes cover, with cells about twice the
  // mean edge length (so a cell holds a few edges) but at least 1/64 of the longest edge;
  // the occupied cells are found by sorting (cell, edge) pairs. A pair is tested only in the
  // cell holding the lower-left corner of the overlap of their boxes, so once.
  double total_length = 0.0, longest = 0.0;
  for (const auto& seg : segments) {
    const double length = std::hypot(seg.max_x - seg.min_x, seg.max_y - seg.min_y);
    total_length += length, longest = std::max(longest, length);
  }
  const double cell = std::max({2.0 * total_length / segments.size(), longest / 64, (max_x - min_x + max_y - min_y) * 1e-9, 1e-300});
  auto cell_of = [&](double v, double origin) { return static_cast<std::int64_t>((v - origin) / cell); };
  auto key_of = [](std::int64_t gx, std::int64_t gy) { return (gx << 32) | gy; };
  std::vector<std::pair<std::int64_t, int>> entries;
  for (int s = 0; s < static_cast<int>(segments.size()); ++s) {
    const auto& seg = segments[s];
    for (std::int64_t gx = cell_of(seg.min_x, min_x); gx <= cell_of(seg.max_x, min_x); ++gx) {
      for (std::int64_t gy = cell_of(seg.min_y, min_y); gy <= cell_of(seg.max_y, min_y); ++gy) entries.emplace_back(key_of(gx, gy), s);
    }
  }
  std::sort(entries.begin(), entries.end());
  auto adjacent = [&](const Segment& s, const Segment& t) {
    if (s.curve != t.curve) return false;
    const int n = static_cast<int>(polylines[s.curve].size());
    if (!is_closed(s.curve)) return s.edge + 1 == t.edge || t.edge + 1 == s.edge;
    return (s.edge + 1) % n == t.edge || (t.edge + 1) % n == s.edge;
  };
  for (size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (size_t i = begin; i < end; ++i) {
      for (size_t j = i + 1; j < end; ++j) {
        const Segment& s = segments[entries[i].second];
        const Segment& t = segments[entries[j].second];
        const double ox = std::max(s.min_x, t.min_x), oy = std::max(s.min_y, t.min_y);
        if (ox > std::min(s.max_x, t.max_x) || oy > std::min(s.max_y, t.max_y)) continue;
        if (key_of(cell_of(ox, min_x), cell_of(oy, min_y)) != entries[begin].first) continue;
        if (adjacent(s, t) || !segments_meet(s, t)) continue;
        return "curve " + std::to_string(s.curve) + " edge " + std::to_string(s.edge) + " meets curve " +
               std::to_string(t.curve) + " edge " + std::to_string(t.edge);
      }
    }
  }
  return "";
}

}  // namespace curvebench
