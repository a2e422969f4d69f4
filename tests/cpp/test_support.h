// Small shared helpers for the C++ tests: hand-made point sets and edge-set comparisons.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "core/point.h"
#include "generators/rose_curve.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench::testing {

// The edges of the closed polygon through points first, first+1, ..., first+n-1.
inline std::vector<Edge> cycle_edges(int n, int first = 0) {
  std::vector<Edge> edges;
  for (int i = 0; i < n; ++i) edges.push_back(make_edge(first + i, first + (i + 1) % n));
  std::sort(edges.begin(), edges.end());
  return edges;
}


// The Voronoi cell of `site` as the triangles (= Voronoi vertices) around it in
// counter-clockwise order. A bounded cell is cyclic. An unbounded (hull) cell is the open
// chain from the triangle on one infinite edge to the triangle on the other; the infinite
// Voronoi vertex closes the cycle between its last and first entry.
inline std::vector<int> voronoi_cell(const DelaunayVoronoi& dv, int site) {
  std::vector<int> cell;
  const int first = dv.site_triangle[site];
  if (first < 0) return cell;
  int t = first;
  do {
    cell.push_back(t);
    t = dv.neighbors[t][(corner_of_site(dv, t, site) + 1) % 3];  // next triangle counter-clockwise
  } while (t != kInfinite && t != first);
  return cell;
}

// Edges between sites of `dv` as edges between input indices (first occurrences).
inline std::vector<Edge> to_input_indices(const DelaunayVoronoi& dv, std::vector<Edge> site_edges) {
  for (Edge& e : site_edges) e = make_edge(dv.input_of_site[e[0]], dv.input_of_site[e[1]]);
  return site_edges;
}

inline std::vector<Edge> sorted(std::vector<Edge> edges) {
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Even-odd: whether q lies inside the closed polygon (the last vertex joins the first).
inline bool inside_polygon(Point2 q, const std::vector<Point2>& polygon) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2 a = polygon[i], b = polygon[j];
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

// n points at angles 2*pi*k/n on a circle (co-circular up to rounding).
inline std::vector<Point2> uniform_circle(int n, double radius = 1.0) {
  std::vector<Point2> points;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    points.push_back({radius * std::cos(t), radius * std::sin(t)});
  }
  return points;
}

// Every integer point on x^2 + y^2 = r^2, counter-clockwise: exactly co-circular input.
// r = 5525 = 5^2 * 13 * 17 gives 180 points.
inline std::vector<Point2> lattice_circle(long r) {
  std::vector<Point2> points;
  for (long x = -r; x <= r; ++x) {
    const long y2 = r * r - x * x;
    const long y = std::lround(std::sqrt(static_cast<double>(y2)));
    if (y * y != y2) continue;
    points.push_back({static_cast<double>(x), static_cast<double>(y)});
    if (y != 0) points.push_back({static_cast<double>(x), static_cast<double>(-y)});
  }
  std::sort(points.begin(), points.end(),
            [](Point2 a, Point2 b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
  return points;
}

// n points evenly spaced along the perimeter of a closed polygon, starting at its first vertex.
inline std::vector<Point2> sample_polygon_evenly(const std::vector<Point2>& polygon, int n) {
  const int m = static_cast<int>(polygon.size());
  double perimeter = 0;
  for (int i = 0; i < m; ++i) perimeter += distance(polygon[i], polygon[(i + 1) % m]);
  std::vector<Point2> points;
  int edge = 0;
  double edge_start = 0;
  for (int k = 0; k < n; ++k) {
    const double s = perimeter * k / n;
    while (edge < m - 1 && s >= edge_start + distance(polygon[edge], polygon[edge + 1]) - 1e-12 * perimeter) {
      edge_start += distance(polygon[edge], polygon[edge + 1]);
      ++edge;
    }
    const Point2 a = polygon[edge], b = polygon[(edge + 1) % m];
    const double f = std::clamp((s - edge_start) / distance(a, b), 0.0, 1.0);
    points.push_back(a + f * (b - a));
  }
  return points;
}

// A five-pointed star: tips at radius 1, inner corners at radius `inner`, a tip first.
inline std::vector<Point2> star_polygon(double inner) {
  std::vector<Point2> polygon;
  for (int k = 0; k < 10; ++k) {
    const double t = std::numbers::pi / 2 + std::numbers::pi * k / 5;
    const double r = k % 2 == 0 ? 1.0 : inner;
    polygon.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return polygon;
}

// The point at parameter t of the rose r = 1 + 0.3 cos 5t, the benchmark's smooth curve.
inline Point2 rose_point(double t) { return curvebench::rose_point(1, 0.3, 5, t); }

// n points at random positions along the rose, in order along it: counter-clockwise by
// parameter. Fixed seed.
// n random parameters in [0, sweep), ascending. Fixed seed.
inline std::vector<double> sorted_random_parameters(int n, double sweep, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, sweep);
  std::vector<double> t(n);
  for (double& value : t) value = angle(rng);
  std::sort(t.begin(), t.end());
  return t;
}

inline std::vector<Point2> rose_in_curve_order(int n, unsigned seed) {
  std::vector<Point2> points;
  for (double value : sorted_random_parameters(n, 2 * std::numbers::pi, seed)) points.push_back(rose_point(value));
  return points;
}

// n points at random angles in [0, sweep) on a circle, in order along it, so that samples
// adjacent along the curve have consecutive indices (sweep 2 pi: a random-angle circle).
inline std::vector<Point2> random_arc(int n, double sweep, unsigned seed, Point2 center = {0, 0}, double radius = 1) {
  std::vector<Point2> points;
  for (double value : sorted_random_parameters(n, sweep, seed)) {
    points.push_back(center + radius * Point2{std::cos(value), std::sin(value)});
  }
  return points;
}

// A random permutation of 0 .. n-1. Fixed seed.
inline std::vector<int> random_order(int n, unsigned seed) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return order;
}

// Cyclic distance between sample indices along a closed curve of n samples.
inline int cyclic_distance(int a, int b, int n) {
  const int d = std::abs(a - b) % n;
  return std::min(d, n - d);
}

}  // namespace curvebench::testing
