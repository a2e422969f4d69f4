// Shape-hull (Peethambaran, Muthuganapathy 2015): the behaviour the spec states on simple
// sets (exact circles, roses and stars; two circles bridged into one polygon; open arcs
// closed by a chord; only an outer boundary on uniform points), its three sculpting rules on
// hand-made cases, and its claims on any input: one simple closed polygon through every hull
// site, every Gabriel edge kept in the shape-hull graph.
#include <gtest/gtest.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <map>
#include <numbers>
#include <queue>
#include <random>
#include <set>
#include <utility>

#include "shape-hull/shape_hull_edges.h"
#include "shape-hull/shape_hull_triangles.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

// The shape-hull of `points` in input indices.
std::vector<Edge> shape_hull_of(const std::vector<Point2>& points) {
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  return sorted(testing::to_input_indices(dv, shape_hull_edges(dv)));
}

// The number of vertices of the polygon if `edges` form exactly one closed polygon (every
// endpoint of degree 2, all connected), else 0.
int closed_polygon_size(const std::vector<Edge>& edges) {
  std::map<int, std::vector<int>> around;
  for (const auto& [a, b] : edges) around[a].push_back(b), around[b].push_back(a);
  for (const auto& [vertex, others] : around) {
    if (others.size() != 2) return 0;
  }
  if (around.empty()) return 0;
  int previous = -1, current = around.begin()->first, visited = 0;
  do {
    const auto& others = around[current];
    const int next = others[0] != previous ? others[0] : others[1];
    previous = current, current = next, ++visited;
  } while (current != around.begin()->first && visited <= static_cast<int>(around.size()));
  return visited == static_cast<int>(around.size()) ? visited : 0;
}

std::vector<Point2> random_angle_circle(int n, unsigned seed, Point2 center = {0, 0}, double radius = 1) {
  return testing::random_arc(n, 2 * std::numbers::pi, seed, center, radius);
}

TEST(ShapeHull, CircleAndRoseWithRandomAnglesAreTheExactPolygon) {
  for (unsigned seed : {1u, 2u, 3u}) {
    EXPECT_EQ(shape_hull_of(random_angle_circle(120, seed)), cycle_edges(120)) << "circle, seed " << seed;
    EXPECT_EQ(shape_hull_of(testing::rose_in_curve_order(120, seed)), cycle_edges(120)) << "rose, seed " << seed;
  }
}

TEST(ShapeHull, CocircularCirclesAreThePolygon) {
  // Every circumcentre is the centre of the circle, inside the shape: nothing is removed.
  EXPECT_EQ(shape_hull_of(testing::uniform_circle(50)), cycle_edges(50));
  EXPECT_EQ(shape_hull_of(testing::lattice_circle(5525)), cycle_edges(180));
}

TEST(ShapeHull, StarSampledAlongItsBoundaryKeepsEveryTip) {
  // The spec's sparse star, where HNN-crust, Crawl and Peel miss tips: 10 corners, inner
  // radius 0.45, sampled evenly with every corner among the samples.
  for (int n : {120, 130, 140}) {
    EXPECT_EQ(shape_hull_of(testing::sample_polygon_evenly(testing::star_polygon(0.45), n)), cycle_edges(n)) << n;
  }
}

TEST(ShapeHull, TwoDisjointCirclesBecomeOnePolygonJoinedByTwoBridges) {
  // Rule b keeps the shape one disk: the triangles in the gap between the circles would split
  // it, so two of them stay and their long edges bridge the circles. Samples between the
  // bridge ends on the arcs that face each other are inside the polygon and get no edges
  // (how many depends on the gap: here 0.5 between unit circles).
  for (unsigned seed : {1u, 2u, 3u}) {
    auto points = random_angle_circle(60, seed);
    const auto right = random_angle_circle(60, seed + 100, {2.5, 0});
    points.insert(points.end(), right.begin(), right.end());
    const auto edges = shape_hull_of(points);
    ASSERT_GT(closed_polygon_size(edges), 0) << seed;
    int bridges = 0;
    std::set<int> on_polygon;
    for (const auto& [a, b] : edges) {
      on_polygon.insert(a), on_polygon.insert(b);
      if ((a < 60) != (b < 60)) {
        ++bridges;
        continue;
      }
      // Within a circle, only neighbours along it (the left circle is 0..59, the right 60..119).
      EXPECT_EQ(testing::cyclic_distance(a % 60, b % 60, 60), 1) << seed;
    }
    EXPECT_EQ(bridges, 2) << seed;
    for (int i = 0; i < 120; ++i) {
      if (on_polygon.count(i)) continue;
      EXPECT_TRUE(i < 60 ? points[i].x > 0.5 : points[i].x < 2.0) << "seed " << seed << ", sample " << i;
    }
  }
}

TEST(ShapeHull, OpenArcIsClosedByOneChord) {
  for (double degrees : {90.0, 180.0, 270.0}) {
    const int n = 120;
    std::vector<Point2> points;
    for (int k = 0; k < n; ++k) {
      const double t = degrees * std::numbers::pi / 180 * k / (n - 1);
      points.push_back({std::cos(t), std::sin(t)});
    }
    std::vector<Edge> path_and_chord;
    for (int k = 0; k + 1 < n; ++k) path_and_chord.push_back({k, k + 1});
    path_and_chord.push_back({0, n - 1});
    EXPECT_EQ(shape_hull_of(points), sorted(path_and_chord)) << degrees;
  }
}

// Every site on the convex hull is a vertex of the polygon, and the polygon is the only one.
void expect_one_polygon_through_the_hull(const std::vector<Point2>& points, const std::string& name) {
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  const auto edges = shape_hull_edges(dv);
  const int size = closed_polygon_size(edges);
  ASSERT_GT(size, 0) << name;
  std::set<int> on_polygon;
  for (const auto& [a, b] : edges) on_polygon.insert(a), on_polygon.insert(b);
  for (int site : dv.hull) EXPECT_TRUE(on_polygon.count(site)) << name << ": hull site " << site;
}

TEST(ShapeHull, UniformPointsGiveOnlyAnOuterBoundary) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point2> points(400);
  for (auto& p : points) p = {coordinate(rng), coordinate(rng)};
  expect_one_polygon_through_the_hull(points, "uniform");
  const int size = closed_polygon_size(shape_hull_of(points));
  EXPECT_LT(size, 300) << "interior points stay isolated";
}

TEST(ShapeHull, NoisyRoseIsOneClosedPolygon) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, 0.02);
  auto points = testing::rose_in_curve_order(120, 5);
  for (auto& p : points) p = p + Point2{noise(rng), noise(rng)};
  const int size = closed_polygon_size(shape_hull_of(points));
  EXPECT_GE(size, 100);
  EXPECT_LE(size, 120);
}

// shape_hull_edges orders its edges with a counting sort: the result must be what the plain
// way gives, every edge between a kept triangle and a removed or unbounded side, once,
// through std::sort. Large enough inputs that sculpting pops hundreds of thousands of
// triangles, far more than the queue announces ahead.
TEST(ShapeHull, EdgesAreTheBoundaryOfTheKeptTrianglesInSortedOrder) {
  std::mt19937 rng(13);
  std::normal_distribution<double> noise(0, 2e-4);
  std::vector<Point2> noisy_rose = testing::rose_in_curve_order(20000, 5);
  for (auto& p : noisy_rose) p = p + Point2{noise(rng), noise(rng)};
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point2> uniform(5000);
  for (auto& p : uniform) p = {coordinate(rng), coordinate(rng)};
  for (const auto& points : {noisy_rose, uniform}) {
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    const std::vector<std::uint8_t> kept = shape_hull_triangles(dv);
    std::vector<Edge> expected;
    for (int t = 0; t < dv.triangle_count(); ++t) {
      for (int corner = 0; corner < 3 && kept[t]; ++corner) {
        const int other = dv.neighbors[t][corner];
        if (other == kInfinite || !kept[other]) {
          expected.push_back(make_edge(dv.triangles[t][(corner + 1) % 3], dv.triangles[t][(corner + 2) % 3]));
        }
      }
    }
    std::sort(expected.begin(), expected.end());
    ASSERT_GT(expected.size(), 100u);
    EXPECT_EQ(shape_hull_edges(dv), expected);
  }
}

// Spec section 2 taken literally, for comparison with the optimised sculpting: a binary heap
// of (radius, triangle) entries (ties: smaller index first, as documented), the rules
// tested in the spec's order at every pop, and the walk of step 2c in exact rational
// arithmetic from the exact centroid to the exact circumcentre: in each triangle, inside if
// the circumcentre is in the closed triangle, else across the edge that runs from a corner
// right of the segment's line to one left of it (a corner on the line counts as left).
std::vector<std::uint8_t> reference_sculpting(const DelaunayVoronoi& dv) {
  using Rational = CGAL::Exact_rational;
  struct Exact {
    Rational x, y;
  };
  auto exact = [&](int site) { return Exact{dv.sites[site].x, dv.sites[site].y}; };
  auto orientation = [](const Exact& a, const Exact& b, const Exact& c) {
    return CGAL::sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  };
  const int count = dv.triangle_count();
  std::vector<std::uint8_t> kept(count, 1), on_boundary(dv.on_hull.begin(), dv.on_hull.end());
  auto outside_across = [&](int t, int corner) { return dv.neighbors[t][corner] == kInfinite || !kept[dv.neighbors[t][corner]]; };
  auto circumcentre_outside = [&](int t) {
    const auto& tri = dv.triangles[t];
    const Exact a = exact(tri[0]), b = exact(tri[1]), c = exact(tri[2]);
    const Exact centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    const Rational bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const Rational d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const Exact centre{a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
    for (int current = t;;) {
      const auto& corners = dv.triangles[current];
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside = inside && orientation(exact(corners[(i + 1) % 3]), exact(corners[(i + 2) % 3]), centre) >= 0;
      if (inside) return false;
      int exit_corner = -1;
      for (int i = 0; i < 3; ++i) {
        const bool from_left = orientation(centroid, centre, exact(corners[(i + 1) % 3])) >= 0;
        const bool to_left = orientation(centroid, centre, exact(corners[(i + 2) % 3])) >= 0;
        if (!from_left && to_left) exit_corner = i;
      }
      if (outside_across(current, exit_corner)) return true;
      current = dv.neighbors[current][exit_corner];
    }
  };
  std::priority_queue<std::pair<double, int>> queue;  // (radius, -triangle): largest radius first
  for (int t = 0; t < count; ++t) {
    if (outside_across(t, 0) || outside_across(t, 1) || outside_across(t, 2)) queue.push({dv.circumradii[t], -t});
  }
  while (!queue.empty()) {
    const int t = -queue.top().second;
    queue.pop();
    const bool outside = circumcentre_outside(t);
    int boundary_edges = 0, boundary_corner = 0;
    for (int i = 0; i < 3; ++i) {
      if (outside_across(t, i)) ++boundary_edges, boundary_corner = i;
    }
    const int apex = dv.triangles[t][boundary_corner];
    if (!outside || boundary_edges != 1 || on_boundary[apex]) continue;
    kept[t] = 0;
    on_boundary[apex] = 1;
    for (int i = 0; i < 3; ++i) {
      if (i != boundary_corner) queue.push({dv.circumradii[dv.neighbors[t][i]], -dv.neighbors[t][i]});
    }
  }
  return kept;
}

// The optimised sculpting (radix-sorted ranks, a swept bit queue, filtered predicates,
// precomputed first crossings, pops left out of the queue when they could only keep) keeps
// exactly the triangles the plain reference keeps, on inputs with many ties and right angles
// (grids), near-duplicates (clusters), noise bands and open arcs.
TEST(ShapeHull, SculptingKeepsWhatAPlainReferenceKeeps) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> gaussian(0, 1);
  int removed = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 20 + static_cast<int>(rng() % 400);
    std::vector<Point2> points;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * unit(rng);
      switch (trial % 5) {
        case 0: points.push_back({unit(rng), unit(rng)}); break;
        case 1: points.push_back({std::floor(12 * unit(rng)), std::floor(12 * unit(rng))}); break;
        case 2: points.push_back(Point2{std::floor(4 * unit(rng)), std::floor(3 * unit(rng))} + 0.05 * Point2{gaussian(rng), gaussian(rng)}); break;
        case 3: {
          const double r = 1 + 0.3 * std::cos(5 * angle) + 0.02 * gaussian(rng);
          points.push_back({r * std::cos(angle), r * std::sin(angle)});
          break;
        }
        default: {
          const double r = 1 + 0.1 * unit(rng);
          points.push_back({r * std::cos(angle / 2), r * std::sin(angle / 2)});
        }
      }
    }
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    const auto expected = reference_sculpting(dv);
    EXPECT_EQ(shape_hull_triangles(dv), expected) << "trial " << trial;
    removed += static_cast<int>(std::count(expected.begin(), expected.end(), 0));
  }
  EXPECT_GT(removed, 1000);  // the sculpting had work to do
}

TEST(ShapeHull, AlwaysOneSimpleClosedPolygonThroughTheHull) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> spread(0, 0.01);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Point2> clustered, grid;
    for (int k = 0; k < 150; ++k) {
      const Point2 cluster{static_cast<double>(k % 3), static_cast<double>(k % 2)};
      clustered.push_back(cluster + Point2{spread(rng), spread(rng)});
    }
    // Integer points: many right angles, so circumcentres exactly on edges.
    for (int k = 0; k < 150; ++k) grid.push_back({std::floor(20 * unit(rng)), std::floor(20 * unit(rng))});
    std::sort(grid.begin(), grid.end(), [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
    expect_one_polygon_through_the_hull(clustered, "clustered " + std::to_string(trial));
    expect_one_polygon_through_the_hull(grid, "grid " + std::to_string(trial));
  }
}

TEST(ShapeHull, GraphKeepsEveryGabrielEdge) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Point2> points(200);
  for (auto& p : points) p = {unit(rng), unit(rng)};
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  const auto kept = shape_hull_triangles(dv);
  std::set<Edge> graph;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    for (int i = 0; kept[t] && i < 3; ++i) graph.insert(make_edge(dv.triangles[t][i], dv.triangles[t][(i + 1) % 3]));
  }
  int gabriel_edges = 0;
  for (int a = 0; a < dv.site_count(); ++a) {
    for (int b = a + 1; b < dv.site_count(); ++b) {
      const Point2 mid = 0.5 * (dv.sites[a] + dv.sites[b]);
      const double radius = distance(dv.sites[a], mid);
      bool empty = true;
      for (int s = 0; s < dv.site_count() && empty; ++s) empty = s == a || s == b || distance(dv.sites[s], mid) >= radius;
      if (!empty) continue;
      ++gabriel_edges;
      EXPECT_TRUE(graph.count({a, b})) << a << " " << b;
    }
  }
  EXPECT_GT(gabriel_edges, 200);
}

TEST(ShapeHull, RemovesABoundaryTriangleExactlyWhenItsCircumcentreIsOutside) {
  // A square around a fifth point. At the centre, each triangle has its right angle there,
  // so its circumcentre is the midpoint of its hull edge: on the border, which counts as inside.
  const std::vector<Point2> square{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  auto centred = square;
  centred.push_back({0, 0});
  EXPECT_EQ(shape_hull_of(centred), cycle_edges(4));
  // Moved up, the top triangle is obtuse at the fifth point: its circumcentre is beyond the
  // top edge, so it goes and the fifth point joins the boundary. The two side triangles then
  // have two boundary edges (dangling) and stay.
  auto raised = square;
  raised.push_back({0, 0.1});
  EXPECT_EQ(shape_hull_of(raised), sorted({{0, 1}, {1, 2}, {2, 4}, {3, 4}, {0, 3}}));
}

TEST(ShapeHull, KeepsAJunctionTriangle) {
  // Two triangles' worth of points joined at the narrow waist of an hourglass: the waist
  // triangle's circumcentre is outside, but removing it would cut the shape in two.
  const std::vector<Point2> hourglass{{-3, -1}, {-3, 1}, {-0.2, 0}, {0.2, 0.05}, {3, -1}, {3, 1}};
  const auto edges = shape_hull_of(hourglass);
  EXPECT_EQ(closed_polygon_size(edges), 6);
}

TEST(ShapeHull, ThreePointsAreTheTriangleAndFewerOrCollinearGiveNoEdges) {
  EXPECT_EQ(shape_hull_of({{0, 0}, {1, 0}, {0.3, 2}}), cycle_edges(3));
  EXPECT_TRUE(shape_hull_of({{0, 0}, {1, 0}}).empty());
  EXPECT_TRUE(shape_hull_of({{0, 0}}).empty());
  EXPECT_TRUE(shape_hull_of({}).empty());
  EXPECT_TRUE(shape_hull_of({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).empty());
  EXPECT_TRUE(shape_hull_triangles(build_delaunay_voronoi(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}})).empty());
}

}  // namespace
}  // namespace curvebench
