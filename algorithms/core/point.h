// Plain geometry value types shared by every stage: a planar point and an index edge.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace curvebench {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

inline Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.y}; }
inline double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Point2 a) { return std::hypot(a.x, a.y); }
inline double distance(Point2 a, Point2 b) { return norm(a - b); }
// The squared distance, for comparing distances without square roots.
inline double squared_distance(Point2 a, Point2 b) { return dot(a - b, a - b); }

// A cheap key of the direction of v, increasing with atan2(v.y, v.x): the "diamond angle",
// v / (|x| + |y|) on the unit diamond, y / (|x| + |y|) in [-1, 1] for x >= 0, continued to
// (-2, 2] for x < 0. NaN for the zero vector.
inline double diamond_angle(Point2 v) {
  const double r = v.y / (std::fabs(v.y) + std::fabs(v.x));
  if (v.x >= 0) return r;
  return v.y >= 0 ? 2 - r : -2 - r;
}

// The point of segment ab closest to p (a itself when the segment is a point).
inline Point2 closest_point_on_segment(Point2 p, Point2 a, Point2 b) {
  const Point2 ab = b - a;
  const double length_squared = dot(ab, ab);
  if (length_squared == 0.0) return a;
  return a + std::clamp(dot(p - a, ab) / length_squared, 0.0, 1.0) * ab;
}

inline double distance_to_segment(Point2 p, Point2 a, Point2 b) { return distance(p, closest_point_on_segment(p, a, b)); }

// An undirected edge between two point indices, stored with first < second.
using Edge = std::array<int, 2>;

inline Edge make_edge(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

}  // namespace curvebench
