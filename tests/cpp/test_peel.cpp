// Peeling the Longest (Parakkat et al. 2018; spec algorithms/peel/specification.md): the peel and
// its symmetric degree filter against a direct transcription of the spec, the behaviour the
// spec reports on circles, a star, two circles and open arcs, reconnection of loose ends, the
// noise-removal step, and inputs too small to peel.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <numbers>
#include <set>

#include "peel/noise_representatives.h"
#include "peel/peel_edges.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

// Peel of `points`, as edges between input indices.
std::vector<Edge> peel_of(const std::vector<Point2>& points, double len = 0.0, bool reference_cb = false) {
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  return sorted(testing::to_input_indices(dv, peel_edges(dv, len, reference_cb)));
}

// The edges of the open path through points first, ..., first + n - 1.
std::vector<Edge> path_edges(int n, int first = 0) {
  std::vector<Edge> edges;
  for (int i = 0; i + 1 < n; ++i) edges.push_back(make_edge(first + i, first + i + 1));
  return edges;
}

// n points at sorted random angles in [from, to) on a circle, centred away from the origin.
std::vector<Point2> arc_at_random_angles(int n, double from, double to, unsigned seed, Point2 centre = {3, 2},
                                         double radius = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(from, to);
  std::vector<double> t(n);
  for (double& value : t) value = angle(rng);
  std::sort(t.begin(), t.end());
  std::vector<Point2> points;
  for (double value : t) points.push_back(centre + radius * Point2{std::cos(value), std::sin(value)});
  return points;
}

std::vector<Point2> uniform_random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point2> points(n);
  for (Point2& p : points) p = {coordinate(rng), coordinate(rng)};
  return points;
}

std::map<int, int> degrees(const std::vector<Edge>& edges) {
  std::map<int, int> degree;
  for (const Edge& e : edges) ++degree[e[0]], ++degree[e[1]];
  return degree;
}

// Spec steps A and B (symmetric rule) transcribed literally on the layer's triangles, with
// sets and linear scans: an edge is peeled if it is a longest side of any triangle, and an
// S-edge (a, b) of length L is dropped if a or b has at least two other S-edges shorter than L.
std::vector<Edge> peel_by_the_letter(const DelaunayVoronoi& dv) {
  auto length = [&](Edge e) { return distance(dv.sites[e[0]], dv.sites[e[1]]); };
  std::set<Edge> all, peeled;
  for (const auto& v : dv.triangles) {
    const Edge sides[3] = {make_edge(v[0], v[1]), make_edge(v[1], v[2]), make_edge(v[2], v[0])};
    for (const Edge& side : sides) {
      all.insert(side);
      if (length(side) >= std::max({length(sides[0]), length(sides[1]), length(sides[2])})) peeled.insert(side);
    }
  }
  std::vector<Edge> s;
  std::set_difference(all.begin(), all.end(), peeled.begin(), peeled.end(), std::back_inserter(s));
  auto shorter_others = [&](int site, Edge e) {
    int count = 0;
    for (const Edge& f : s) count += f != e && (f[0] == site || f[1] == site) && length(f) < length(e);
    return count;
  };
  std::vector<Edge> kept;
  for (const Edge& e : s) {
    if (shorter_others(e[0], e) <= 1 && shorter_others(e[1], e) <= 1) kept.push_back(e);
  }
  return kept;
}

TEST(Peel, MatchesTheSpecTranscribedLiterally) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const DelaunayVoronoi dv = build_delaunay_voronoi(uniform_random_points(300, seed));
    EXPECT_EQ(peel_edges(dv), peel_by_the_letter(dv)) << seed;
  }
  const DelaunayVoronoi star = build_delaunay_voronoi(testing::sample_polygon_evenly(testing::star_polygon(0.45), 120));
  EXPECT_EQ(peel_edges(star), peel_by_the_letter(star));
}

TEST(Peel, RandomAngleCirclesAndRosesAreExactPolygons) {
  // Spec section 4: exact closed polygons, 9 of 9.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    EXPECT_EQ(peel_of(arc_at_random_angles(120, 0, 2 * std::numbers::pi, seed)), cycle_edges(120)) << seed;
    EXPECT_EQ(peel_of(testing::rose_in_curve_order(120, seed)), cycle_edges(120)) << seed;
  }
}

TEST(Peel, ResultDoesNotDependOnInputOrder) {
  // Step A is a set and the symmetric step B reads only lengths: shuffling the input only
  // renames the edges. The star has the sharp corners where the reference rule is orientation
  // dependent.
  const auto star = testing::sample_polygon_evenly(testing::star_polygon(0.45), 120);
  const auto order = testing::random_order(120, 7);
  std::vector<Point2> shuffled;
  for (int i : order) shuffled.push_back(star[i]);
  std::vector<Edge> renamed;
  for (const Edge& e : peel_of(shuffled)) renamed.push_back(make_edge(order[e[0]], order[e[1]]));
  EXPECT_EQ(sorted(renamed), peel_of(star));
}

TEST(Peel, StarIsExactAwayFromItsTips) {
  // Spec section 4: not exact, a few wrong edges near the tips. Evenly sampled, each tip is
  // cut off by a chord; samples more than two steps from every tip keep exactly their two
  // boundary edges.
  const int n = 120, per_tip = n / 5;  // sample_polygon_evenly starts at a tip
  const auto edges = peel_of(testing::sample_polygon_evenly(testing::star_polygon(0.45), n));
  auto near_a_tip = [&](int i) { return testing::cyclic_distance(i, (i + per_tip / 2) / per_tip * per_tip % n, n) <= 2; };
  const auto truth = cycle_edges(n);
  int extra = 0;
  for (const Edge& e : edges) {
    if (std::binary_search(truth.begin(), truth.end(), e)) continue;
    ++extra;
    EXPECT_TRUE(near_a_tip(e[0]) && near_a_tip(e[1])) << e[0] << " " << e[1];
  }
  EXPECT_GE(extra, 1);
  EXPECT_LE(extra, 5);
  for (const Edge& e : truth) {
    if (near_a_tip(e[0]) && near_a_tip(e[1])) continue;
    EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), e)) << e[0] << " " << e[1];
  }
}

TEST(Peel, TwoDisjointCirclesAreBothExactWithoutABridge) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    auto points = arc_at_random_angles(60, 0, 2 * std::numbers::pi, seed, {0, 0});
    const auto second = arc_at_random_angles(60, 0, 2 * std::numbers::pi, seed + 10, {3.5, 0.5}, 1.2);
    points.insert(points.end(), second.begin(), second.end());
    auto expected = cycle_edges(60);
    const auto other = cycle_edges(60, 60);
    expected.insert(expected.end(), other.begin(), other.end());
    EXPECT_EQ(peel_of(points), sorted(expected)) << seed;
  }
}

TEST(Peel, OpenArcsOf90And180DegreesStayOpenPaths) {
  for (const double degrees_of_arc : {90.0, 180.0}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const auto arc = arc_at_random_angles(120, 0, degrees_of_arc * std::numbers::pi / 180, seed);
      EXPECT_EQ(peel_of(arc), path_edges(120)) << degrees_of_arc << " " << seed;
    }
  }
}

TEST(Peel, ArcsOf270DegreesAreClosedByTheChordAcrossTheMouth) {
  // Spec section 4: the chord joining the ends is a hull edge that is not the longest side of
  // its triangle, so it survives, and the degree filter sees degree 2 at both ends.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const auto arc = arc_at_random_angles(120, 0, 1.5 * std::numbers::pi, seed);
    EXPECT_EQ(peel_of(arc), cycle_edges(120)) << seed;
  }
}

TEST(Peel, DegreeFilterLeavesAtMostTwoEdgesPerSite) {
  // Without ties an edge survives at a site only if at most one other S-edge there is
  // shorter: at most the two shortest survive. Uniform points give sites of S-degree 3 and more.
  for (unsigned seed : {4u, 5u}) {
    const auto edges = peel_of(uniform_random_points(500, seed));
    for (const auto& [site, degree] : degrees(edges)) EXPECT_LE(degree, 2) << site;
    EXPECT_GT(edges.size(), 250u);  // spec section 4: about 0.8 n edges
    EXPECT_LT(edges.size(), 500u);
  }
}

// A centre (site 0) and three spokes of the given lengths at the given angles (degrees), the
// centre inside the triangle of the tips: the Delaunay triangulation is the fan around the
// centre, and each rim side is the longest side of its triangle.
std::vector<Point2> spokes(std::array<double, 3> lengths, std::array<double, 3> degrees_of_spoke) {
  std::vector<Point2> points{{5, 5}};
  for (int k = 0; k < 3; ++k) {
    const double t = degrees_of_spoke[k] * std::numbers::pi / 180;
    points.push_back(Point2{5, 5} + lengths[k] * Point2{std::cos(t), std::sin(t)});
  }
  return points;
}

TEST(Peel, DegreeFilterDropsTheLongestOfThreeEdgesAtASite) {
  // The peel keeps the three spokes; at the centre the longest has two shorter S-edges
  // (spec step B). A tie is not "shorter": equal spokes all survive.
  EXPECT_EQ(peel_of(spokes({1, 1.2, 1.5}, {0, 120, 240})), (std::vector<Edge>{{0, 1}, {0, 2}}));
  EXPECT_EQ(peel_of(spokes({1.5, 1.5, 1.5}, {0, 120, 240})), (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}}));
}

TEST(Peel, ReferenceDegreeRuleKeepsASubsetOfTheSymmetricOne) {
  // The reference cb counts a's other neighbours besides b's, so it can only fire more often.
  // It needs a neighbour of a nearer to b than a is that is not a Delaunay triangle's third
  // corner: rare, but over ten uniform sets of 400 it happens.
  int differing = 0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const auto points = uniform_random_points(400, seed);
    const auto symmetric = peel_of(points), reference = peel_of(points, 0.0, true);
    EXPECT_TRUE(std::includes(symmetric.begin(), symmetric.end(), reference.begin(), reference.end())) << seed;
    differing += reference != symmetric;
  }
  EXPECT_GE(differing, 1);
}

TEST(Peel, ReconnectionJoinsLooseEndsAndRunsOnThroughIsolatedSites) {
  // Spokes 1, 1.2, 1.3 at 0, 150 and 240 degrees: step B drops spoke 3, leaving the path
  // 1 - 0 - 2 with loose ends 1 (L = 1) and 2 (L = 1.2). Rim lengths: d(1, 3) = 1.997,
  // d(1, 2) = 2.126, d(2, 3) = 1.769 (spec step C).
  const auto points = spokes({1, 1.2, 1.3}, {0, 150, 240});
  EXPECT_EQ(peel_of(points), (std::vector<Edge>{{0, 1}, {0, 2}}));
  // len = 1.5: only 2 reaches a free neighbour, 3 (1.769 < 1.8). The new edge (3, 2) is
  // scanned in turn; 3 has no other edge, and its nearest free neighbour is the centre
  // (1.3 < 1.5 * 1.769), through the spoke step B dropped. 1 reaches nothing below 1.5.
  EXPECT_EQ(peel_of(points, 1.5), (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}, {2, 3}}));
  // len = 2.1: 1 reaches 3 (1.997 < 2.1) and 2 reaches 3 (1.769 < 2.52, nearer than 1):
  // the quadrilateral 0 - 1 - 3 - 2, whichever loose end is scanned first.
  EXPECT_EQ(peel_of(points, 2.1), (std::vector<Edge>{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
}

TEST(Peel, ReconnectionOnlyAddsDelaunayEdgesAtLooseEnds) {
  // Spec step C on uniform points: the result contains the unreconnected one, every added
  // edge is a Delaunay edge, and one of its ends had at most one edge before (it was a loose
  // end, or an isolated site reached by a chain).
  const DelaunayVoronoi dv = build_delaunay_voronoi(uniform_random_points(400, 9));
  const auto plain = peel_edges(dv), reconnected = peel_edges(dv, 2.0);
  EXPECT_TRUE(std::includes(reconnected.begin(), reconnected.end(), plain.begin(), plain.end()));
  EXPECT_GT(reconnected.size(), plain.size());
  std::set<Edge> delaunay;
  for (const auto& v : dv.triangles) {
    for (int k = 0; k < 3; ++k) delaunay.insert(make_edge(v[k], v[(k + 1) % 3]));
  }
  auto before = degrees(plain);
  for (const Edge& e : reconnected) {
    EXPECT_TRUE(delaunay.count(e)) << e[0] << " " << e[1];
    if (std::binary_search(plain.begin(), plain.end(), e)) continue;
    EXPECT_LE(std::min(before[e[0]], before[e[1]]), 1) << e[0] << " " << e[1];
  }
}

TEST(Peel, NoiseRepresentativesOfAHexagonIsItsCentre) {
  // The centre sees six neighbours at distance 1 (ratio 1 < 2); the corners are hull sites.
  std::vector<Point2> points{{5, 5}};
  for (int k = 0; k < 6; ++k) points.push_back(Point2{5, 5} + Point2{std::cos(k * 1.047 + 0.1), std::sin(k * 1.047 + 0.1)});
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  const auto kept = noise_representatives(dv, 0.5);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(dv.input_of_site[kept[0]], 0);
}

TEST(Peel, NoiseRepresentativesRejectUnevenNeighbourhoods) {
  // Moving one corner of the hexagon to 0.3 from the centre, inside the hull: the centre and
  // that point both have a longest Delaunay edge more than twice their shortest, and the
  // other five are hull sites, so nothing is kept.
  std::vector<Point2> points{{5, 5}, {5.3, 5}};
  for (int k = 1; k < 6; ++k) points.push_back(Point2{5, 5} + Point2{std::cos(k * 1.047), std::sin(k * 1.047)});
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  EXPECT_EQ(std::count(dv.on_hull.begin(), dv.on_hull.end(), 1), 5);
  EXPECT_TRUE(noise_representatives(dv, 0.1).empty());
}

TEST(Peel, NoiseRepresentativesAreAGreedyCover) {
  // A noisy circle band: representatives are interior sites passing the ratio test, pairwise
  // at least tau apart, and every other interior site passing the test is within tau of one.
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, 0.02);
  std::vector<Point2> points = arc_at_random_angles(1500, 0, 2 * std::numbers::pi, 3, {20, 10}, 1.0);
  for (Point2& p : points) p = p + Point2{noise(rng), noise(rng)};
  const DelaunayVoronoi dv = build_delaunay_voronoi(points);
  const double tau = 0.08;
  const auto kept = noise_representatives(dv, tau);
  ASSERT_GT(kept.size(), 20u);
  EXPECT_LT(kept.size(), 300u);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    EXPECT_FALSE(dv.on_hull[kept[i]]);
    for (std::size_t j = i + 1; j < kept.size(); ++j) EXPECT_GE(distance(dv.sites[kept[i]], dv.sites[kept[j]]), tau);
  }
  std::vector<double> shortest(dv.site_count(), 1e300), longest(dv.site_count(), 0);
  for (const auto& v : dv.triangles) {
    for (int k = 0; k < 3; ++k) {
      const double d = distance(dv.sites[v[k]], dv.sites[v[(k + 1) % 3]]);
      for (int s : {v[k], v[(k + 1) % 3]}) shortest[s] = std::min(shortest[s], d), longest[s] = std::max(longest[s], d);
    }
  }
  for (int s : kept) EXPECT_LT(longest[s], 2 * shortest[s]);
  for (int s = 0; s < dv.site_count(); ++s) {
    if (dv.on_hull[s] || !(longest[s] < 2 * shortest[s])) continue;
    bool covered = false;
    for (int r : kept) covered = covered || distance(dv.sites[s], dv.sites[r]) < tau;
    EXPECT_TRUE(covered) << s;
  }
  // Then peeled, the representatives trace the circle: every site keeps two edges.
  std::vector<Point2> reduced;
  for (int s : kept) reduced.push_back(dv.sites[s]);
  int closed = 0;
  for (const auto& [site, degree] : degrees(peel_of(reduced))) closed += degree == 2;
  EXPECT_GT(closed, static_cast<int>(0.8 * reduced.size()));
}

TEST(Peel, ThreeSitesKeepTheTwoShorterSides) {
  // One triangle: its longest side is peeled (spec step A).
  EXPECT_EQ(peel_of({{1, 1}, {5, 1}, {1, 4}}), (std::vector<Edge>{{0, 1}, {0, 2}}));
  // Two tied longest sides are both peeled: "longest" is non-strict.
  EXPECT_EQ(peel_of({{1, 1}, {3, 1}, {2, 6}}), (std::vector<Edge>{{0, 1}}));
  // With len = 3 both loose ends of the base reach the apex (sqrt 26 < 3 * 2): both ends'
  // counts are taken before either edge is appended (spec step C).
  EXPECT_EQ(peel_of({{1, 1}, {3, 1}, {2, 6}}, 3.0), (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(peel_of({{1, 1}, {3, 1}, {2, 6}}, 2.5), (std::vector<Edge>{{0, 1}}));
}

TEST(Peel, InputsWithoutATriangleGiveNothing) {
  // Fewer than three sites or all collinear: no finite triangle, no edges (spec section 2).
  for (const std::vector<Point2>& points : {std::vector<Point2>{}, std::vector<Point2>{{1, 1}},
                                           std::vector<Point2>{{1, 1}, {2, 2}},
                                           std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}}) {
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    EXPECT_TRUE(peel_edges(dv, 2.0).empty()) << points.size();
    EXPECT_TRUE(noise_representatives(dv, 1.0).empty()) << points.size();
  }
}

}  // namespace
}  // namespace curvebench
