// The shared Delaunay/Voronoi layer: array invariants, cells, duplicates, and the
// degenerate configurations it promises to handle (co-circular, collinear, ties).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <set>

#include "test_support.h"
#include "labeling/side_of_tangent_line.h"
#include "voronoi/convex_hull_membership.h"
#include "voronoi/delaunay_voronoi.h"
#include "voronoi/sort_by_decreasing_circumradius.h"

namespace curvebench {
namespace {

using testing::lattice_circle;
using testing::random_order;
using testing::rose_in_curve_order;
using testing::uniform_circle;
using testing::voronoi_cell;

void expect_consistent(const DelaunayVoronoi& dv) {
  ASSERT_EQ(dv.dimension, 2);
  int cell_vertices = 0;
  for (int s = 0; s < dv.site_count(); ++s) {
    const auto cell = voronoi_cell(dv, s);
    ASSERT_FALSE(cell.empty()) << "site " << s;
    for (int t : cell) EXPECT_NE(std::find(dv.triangles[t].begin(), dv.triangles[t].end(), s), dv.triangles[t].end());
    cell_vertices += static_cast<int>(cell.size());
  }
  EXPECT_EQ(cell_vertices, 3 * dv.triangle_count());  // every triangle is in its three sites' cells
  for (int t = 0; t < dv.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (other == kInfinite) continue;
      const auto& nb = dv.neighbors[other];
      EXPECT_TRUE(nb[0] == t || nb[1] == t || nb[2] == t) << "neighbour relation is symmetric";
    }
    const auto& tri = dv.triangles[t];
    EXPECT_GT(cross(dv.sites[tri[1]] - dv.sites[tri[0]], dv.sites[tri[2]] - dv.sites[tri[0]]), 0) << "counter-clockwise";
  }
  EXPECT_EQ(static_cast<int>(dv.hull.size()), std::count(dv.on_hull.begin(), dv.on_hull.end(), 1));
}

TEST(VoronoiLayer, ArraysAreConsistentOnRandomAndCocircularInput) {
  expect_consistent(build_delaunay_voronoi(uniform_circle(50)));
  expect_consistent(build_delaunay_voronoi(lattice_circle(5525)));
  std::vector<Point2> grid;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) grid.push_back({double(i), double(j)});
  expect_consistent(build_delaunay_voronoi(grid));
}

// The numbering (number_sites_and_faces): sites keep the input order when the points run
// along the curve in either direction and are put in Z order otherwise; triangles follow
// their smallest site. Either way neighbours are close in the arrays. On the rose, the median
// gap between neighbouring triangles is 2 (4 in Z order), and consecutive sites are 0.0015
// apart at the median (0.0061 in Z order). A random numbering would give gaps of about 0.29
// of the 7,335 triangles, and the shuffled input's consecutive points are 1.42 apart.
TEST(VoronoiLayer, SitesKeepAnOrderAlongTheCurveAndAreOtherwiseInZOrder) {
  auto median = [](std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  auto neighbour_gaps = [](const DelaunayVoronoi& dv) {
    std::vector<double> gaps;
    for (int t = 0; t < dv.triangle_count(); ++t) {
      for (int other : dv.neighbors[t]) {
        if (other != kInfinite) gaps.push_back(std::abs(other - t));
      }
    }
    return gaps;
  };
  auto site_steps = [](const std::vector<Point2>& sites) {
    std::vector<double> steps;
    for (std::size_t s = 0; s + 1 < sites.size(); ++s) steps.push_back(distance(sites[s], sites[s + 1]));
    return steps;
  };
  const auto counter_clockwise = rose_in_curve_order(4000, 5);
  std::vector<Point2> shuffled;
  for (int i : random_order(4000, 6)) shuffled.push_back(counter_clockwise[i]);
  // On a circle every consecutive pair is a hull edge, in one face and one orientation only.
  const auto circle = uniform_circle(3000);
  struct Case {
    std::vector<Point2> points;
    bool along_the_curve;
  };
  const Case cases[] = {{counter_clockwise, true},
                        {{counter_clockwise.rbegin(), counter_clockwise.rend()}, true},
                        {shuffled, false},
                        {circle, true},
                        {{circle.rbegin(), circle.rend()}, true}};
  for (const auto& [points, along_the_curve] : cases) {
    const auto dv = build_delaunay_voronoi(points);
    expect_consistent(dv);
    const int n = static_cast<int>(points.size());
    ASSERT_EQ(dv.site_count(), n);
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(dv.input_of_site == identity, along_the_curve);
    for (int s = 0; s < n; ++s) {
      ASSERT_EQ(dv.sites[s], points[dv.input_of_site[s]]);
      ASSERT_EQ(dv.site_of_input[dv.input_of_site[s]], s);
    }
    std::vector<int> smallest_sites;
    for (const auto& tri : dv.triangles) smallest_sites.push_back(*std::min_element(tri.begin(), tri.end()));
    EXPECT_TRUE(std::ranges::is_sorted(smallest_sites));
    EXPECT_LT(median(neighbour_gaps(dv)), 20);
    EXPECT_LT(median(site_steps(dv.sites)), 0.02);
  }
  EXPECT_GT(median(site_steps(shuffled)), 0.5);
}

TEST(VoronoiLayer, ExactlyCocircularSitesGiveOneDegenerateVoronoiVertex) {
  const auto points = lattice_circle(5525);
  ASSERT_EQ(points.size(), 180u);
  const auto dv = build_delaunay_voronoi(points);
  EXPECT_EQ(dv.triangle_count(), 178);
  EXPECT_EQ(static_cast<int>(dv.hull.size()), 180);
  for (int t = 0; t < dv.triangle_count(); ++t) {
    EXPECT_NEAR(dv.circumcenters[t].x, 0.0, 1e-9 * 5525);
    EXPECT_NEAR(dv.circumcenters[t].y, 0.0, 1e-9 * 5525);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(is_degenerate_voronoi_edge(dv, t, k), dv.neighbors[t][k] != kInfinite);
    }
  }
}

TEST(VoronoiLayer, HullCellWalkCoversTheWholeFan) {
  const auto dv = build_delaunay_voronoi(uniform_circle(12));
  int total = 0;
  for (int s : dv.hull) {
    const auto cell = voronoi_cell(dv, s);
    // The chain starts on the clockwise hull edge and ends on the counter-clockwise one.
    const int first = cell.front(), last = cell.back();
    EXPECT_EQ(dv.neighbors[first][(corner_of_site(dv, first, s) + 2) % 3], kInfinite);
    EXPECT_EQ(dv.neighbors[last][(corner_of_site(dv, last, s) + 1) % 3], kInfinite);
    total += static_cast<int>(cell.size());
  }
  EXPECT_EQ(total, 3 * dv.triangle_count());
}

TEST(VoronoiLayer, TheVoronoiVerticesAroundASiteAreItsCellThenTheInfiniteVertexOnTheHull) {
  for (const auto& points : {uniform_circle(12), rose_in_curve_order(300, 3)}) {
    const auto dv = build_delaunay_voronoi(points);
    for (int s = 0; s < dv.site_count(); ++s) {
      std::vector<int> around;
      for_each_voronoi_vertex_around(dv, s, [&](int t) { around.push_back(t); });
      std::vector<int> expected = voronoi_cell(dv, s);
      if (dv.on_hull[s]) expected.push_back(kInfinite);
      EXPECT_EQ(around, expected) << "site " << s;
    }
  }
}

TEST(VoronoiLayer, DuplicatesMapToTheirFirstOccurrence) {
  const std::vector<Point2> points{{0, 0}, {1, 0}, {0, 0}, {0, 1}, {1, 0}, {1, 1}};
  const auto dv = build_delaunay_voronoi(points);
  EXPECT_EQ(dv.site_count(), 4);
  EXPECT_EQ(dv.input_of_site, (std::vector<int>{0, 1, 3, 5}));
  EXPECT_EQ(dv.site_of_input, (std::vector<int>{0, 1, 0, 2, 1, 3}));
  EXPECT_EQ(dv.triangle_count(), 2);
  for (int s = 0; s < 4; ++s) EXPECT_EQ(dv.sites[s], points[dv.input_of_site[s]]);
}

TEST(VoronoiLayer, LowDimensionalInputHasNoTriangles) {
  EXPECT_EQ(build_delaunay_voronoi(std::vector<Point2>{}).dimension, -1);
  EXPECT_EQ(build_delaunay_voronoi(std::vector<Point2>{{1, 1}, {1, 1}}).dimension, 0);
  const auto line = build_delaunay_voronoi(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {5, 5}});
  EXPECT_EQ(line.dimension, 1);
  EXPECT_EQ(line.triangle_count(), 0);
}

TEST(VoronoiLayer, TangentLineSideIsExactIncludingTies) {
  // p = (0,0). Triangle {p, (1,1), (-1,1)} has circumcentre (0,1); triangle {p, (2,0), (1,1)}
  // has circumcentre (1,0), exactly on the line through p orthogonal to (0,1).
  const std::vector<Point2> points{{0, 0}, {1, 1}, {-1, 1}, {2, 0}};
  const auto dv = build_delaunay_voronoi(points);
  ASSERT_EQ(dv.triangle_count(), 2);
  const int up = std::abs(dv.circumcenters[0].y - 1) < 1e-12 ? 0 : 1;
  const int right = 1 - up;
  EXPECT_EQ(side_of_tangent_line(dv, 0, up, right), 0);
  EXPECT_EQ(side_of_tangent_line(dv, 0, up, up), 1);
  // Seen from (1,1): (0,1) - (1,1) = (-1,0) and (1,0) - (1,1) = (0,-1) are orthogonal, a tie too.
  EXPECT_EQ(side_of_tangent_line(dv, 1, up, right), 0);
}

TEST(VoronoiLayer, CircumcentreIsFiniteWhenTheCrossProductRoundsToZero) {
  // cross(ab, ac) = 1e-340 underflows to 0 in double; the exact centre is (-3.5, 4.5) * 1e-170.
  const auto dv = build_delaunay_voronoi(std::vector<Point2>{{0, 0}, {1e-170, 1e-170}, {2e-170, 3e-170}});
  ASSERT_EQ(dv.triangle_count(), 1);
  EXPECT_DOUBLE_EQ(dv.circumcenters[0].x, -3.5e-170);
  EXPECT_DOUBLE_EQ(dv.circumcenters[0].y, 4.5e-170);
  EXPECT_TRUE(std::isfinite(dv.circumradii[0]) && std::isfinite(dv.circumcenter_errors[0]));
}

TEST(VoronoiLayer, ConvexHullMembership) {
  const auto dv = build_delaunay_voronoi(std::vector<Point2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}});
  int wedge = 0;
  EXPECT_TRUE(in_convex_hull(dv, {2, 2}, wedge));
  EXPECT_TRUE(in_convex_hull(dv, {4, 2}, wedge));  // on the boundary counts as inside
  EXPECT_FALSE(in_convex_hull(dv, {4.0000001, 2}, wedge));
  EXPECT_FALSE(in_convex_hull(dv, {-1, -1}, wedge));
}

TEST(VoronoiLayer, ConvexHullMembershipFromAnyWedgeHint) {
  // Integer points near a circle: hundreds of hull vertices, and orientations exact in double,
  // so a brute-force test over every hull edge is the reference.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  std::vector<Point2> points;
  for (int i = 0; i < 400; ++i) {
    const double t = angle(rng);
    points.push_back({std::round(1e5 * std::cos(t)), std::round(1e5 * std::sin(t))});
  }
  const auto dv = build_delaunay_voronoi(points);
  const auto& h = dv.hull;
  const int m = static_cast<int>(h.size());
  ASSERT_GT(m, 100);
  auto brute_force = [&](Point2 q) {
    for (int i = 0; i < m; ++i) {
      if (cross(dv.sites[h[(i + 1) % m]] - dv.sites[h[i]], q - dv.sites[h[i]]) < 0) return false;
    }
    return true;
  };
  std::uniform_int_distribution<int> coordinate(-120000, 120000), hint(-5, m + 5);
  int wedge = 0;  // carried from query to query, as the labeler does
  ConvexHullMembership membership(dv);
  for (int k = 0; k < 4000; ++k) {
    // A quarter of the queries lie on the boundary (a hull vertex or the midpoint of a hull
    // edge), a quarter just outside the middle of a hull edge, where only that edge's wedge
    // tells them apart from the inside; the rest anywhere around the hull.
    const Point2 a = dv.sites[h[k % m]], b = dv.sites[h[(k + 1) % m]];
    const Point2 middle{(a.x + b.x) / 2, (a.y + b.y) / 2}, outward{0.01 * (b.y - a.y), -0.01 * (b.x - a.x)};
    const Point2 q = k % 4 == 0   ? (k % 8 == 0 ? a : middle)
                     : k % 4 == 1 ? middle + outward
                                  : Point2{double(coordinate(rng)), double(coordinate(rng))};
    const bool expected = brute_force(q);
    int random_hint = hint(rng);
    EXPECT_EQ(in_convex_hull(dv, q, random_hint), expected) << q.x << " " << q.y;
    EXPECT_EQ(in_convex_hull(dv, q, wedge), expected) << q.x << " " << q.y;
    int fresh_hint = 0;
    EXPECT_EQ(in_convex_hull(dv, q, fresh_hint), expected) << q.x << " " << q.y;
    EXPECT_EQ(membership.contains(q), expected) << q.x << " " << q.y;
  }
}

// ConvexHullMembership decides most queries by a disk per sector and must agree with the exact
// test everywhere: on a hull of three corners (each edge spans many sectors), far from the
// origin (the disks' margins scale with the coordinates), just inside and just outside edges.
TEST(VoronoiLayer, ConvexHullMembershipAgreesWithTheExactTest) {
  std::mt19937 rng(11);
  for (const Point2 offset : {Point2{0, 0}, Point2{3e6, -5e6}}) {
    std::vector<Point2> points = {{0, 0}, {40000, 1000}, {2000, 30000}};
    std::uniform_int_distribution<int> inside(1000, 9000);
    for (int i = 0; i < 50; ++i) points.push_back({double(inside(rng)), double(inside(rng))});
    for (Point2& p : points) p = p + offset;
    const auto dv = build_delaunay_voronoi(points);
    ASSERT_EQ(dv.hull.size(), 3u);
    ConvexHullMembership membership(dv);
    std::uniform_int_distribution<int> coordinate(-5000, 45000);
    for (int k = 0; k < 20000; ++k) {
      const Point2 q = Point2{double(coordinate(rng)), double(coordinate(rng))} + offset;
      int wedge = 0;
      EXPECT_EQ(membership.contains(q), in_convex_hull(dv, q, wedge)) << q.x << " " << q.y;
    }
    for (std::size_t i = 0; i < 3; ++i) {  // on each edge, and a unit to either side
      const Point2 a = dv.sites[dv.hull[i]], b = dv.sites[dv.hull[(i + 1) % 3]];
      const Point2 middle{(a.x + b.x) / 2, (a.y + b.y) / 2};
      EXPECT_TRUE(membership.contains(middle));
      EXPECT_TRUE(membership.contains(a));
      const Point2 normal = Point2{b.y - a.y, a.x - b.x};
      const double unit = 1 / std::hypot(normal.x, normal.y);
      EXPECT_FALSE(membership.contains(middle + unit * normal));
      EXPECT_TRUE(membership.contains(middle + (-unit) * normal));
    }
  }
}

// Hull edges through collinear sites (`hull` keeps them): a lattice, its hull listed from a
// corner and from the middle of an edge. Points on the edges' lines beyond their ends are
// outside; in_convex_hull's fan from hull[0] has flat wedges along the edges through it, where
// it once answered inside.
TEST(VoronoiLayer, ConvexHullMembershipOnEdgesThroughCollinearSites) {
  for (const Point2 first : {Point2{0, 0}, Point2{5, 0}}) {
    std::vector<Point2> lattice = {first};
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        if (Point2{double(i), double(j)} != first) lattice.push_back({double(i), double(j)});
      }
    }
    const auto dv = build_delaunay_voronoi(lattice);
    ASSERT_EQ(dv.sites[dv.hull[0]], first);  // the fan's origin: a corner, then mid-edge
    ConvexHullMembership membership(dv);
    int wedge = 0;
    for (int i = -4; i <= 26; ++i) {
      for (int j = -4; j <= 26; ++j) {
        const Point2 q{i / 2.0, j / 2.0};
        const bool inside = q.x >= 0 && q.x <= 11 && q.y >= 0 && q.y <= 11;
        EXPECT_EQ(in_convex_hull(dv, q, wedge), inside) << q.x << " " << q.y;
        EXPECT_EQ(membership.contains(q), inside) << q.x << " " << q.y;
      }
    }
  }
}

// for_each_by_decreasing_circumradius is the full sort with the entries reached before their
// turn left out, also when reaching changes during the visits and radii tie (a grid's
// triangles all have one circumradius; the rose's do not), and whatever the list's order.
TEST(VoronoiLayer, LazyRadiusOrderIsTheSortWithoutTheReachedEntries) {
  std::vector<Point2> grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) grid.push_back({double(i), double(j)});
  std::vector<Point2> rose = rose_in_curve_order(3000, 7);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.002);
  for (Point2& p : rose) p = p + Point2{noise(rng), noise(rng)};
  for (const auto& points : {grid, rose}) {
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    std::vector<int> list;
    for (int t = 0; t < dv.triangle_count(); t += 1 + t % 3) list.push_back(t);
    // A visit reaches the visited triangle's neighbours, as a walk from it would.
    auto visits_in_order = [&](auto&& for_each) {
      std::vector<std::uint8_t> reached(dv.triangle_count(), 0);
      std::vector<int> visited;
      for_each([&](int t) { return reached[t] != 0; }, [&](int t) {
        visited.push_back(t);
        reached[t] = 1;
        for (int next : dv.neighbors[t]) {
          if (next != kInfinite) reached[next] = 1;
        }
      });
      return visited;
    };
    const std::vector<int> expected = visits_in_order([&](auto reached, auto visit) {
      std::vector<int> sorted_list = list;
      sort_by_decreasing_circumradius(dv, sorted_list);
      for (int t : sorted_list) {
        if (!reached(t)) visit(t);
      }
    });
    std::vector<int> shuffled = list;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    for (const auto& given : {list, shuffled}) {
      int announced = 0;
      const std::vector<int> lazy = visits_in_order([&](auto reached, auto visit) {
        for_each_by_decreasing_circumradius(dv, given, reached, visit, [&](int) { ++announced; });
      });
      EXPECT_EQ(lazy, expected) << points.size() << " points";
      EXPECT_GT(announced, 0);
    }
    EXPECT_LT(expected.size(), list.size()) << "entries reached before their turn";
  }
}

}  // namespace
}  // namespace curvebench
