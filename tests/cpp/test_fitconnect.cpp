// FitConnect (algorithms/fitconnect/specification.md): the behaviours of its sections 2 and 4
// on small hand-made inputs, fixed seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/distinct_points.h"
#include "fitconnect/angular_order.h"
#include "fitconnect/fitconnect.h"
#include "fitconnect/fitted_neighborhoods.h"
#include "fitconnect/hyper_circle_fit.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

std::vector<int> degrees_of(const std::vector<Edge>& edges, int n) {
  std::vector<int> degree(n, 0);
  for (const Edge& e : edges) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  return degree;
}

std::vector<Edge> path_edges(int n, int first = 0) {
  std::vector<Edge> edges;
  for (int i = 0; i + 1 < n; ++i) edges.push_back(make_edge(first + i, first + i + 1));
  return edges;
}

// Every coordinate moved by a uniform offset in [-amplitude, amplitude].
std::vector<Point2> jittered(std::vector<Point2> points, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-amplitude, amplitude);
  for (Point2& p : points) {
    p.x += offset(rng);
    p.y += offset(rng);
  }
  return points;
}

TEST(FitConnect, HyperFitRecoversACircle) {
  std::vector<Point2> points;
  for (double t : {0.3, 0.5, 0.9, 1.4, 2.0}) points.push_back({2.0 + 3.0 * std::cos(t), -1.0 + 3.0 * std::sin(t)});
  const FittedCircle circle = hyper_circle_fit(points);
  EXPECT_NEAR(circle.center.x, 2.0, 1e-9);
  EXPECT_NEAR(circle.center.y, -1.0, 1e-9);
  EXPECT_NEAR(circle.radius, 3.0, 1e-9);
}

TEST(FitConnect, HyperFitOfCollinearPointsTakesTheDegenerateBranch) {
  // D = 0 exactly: the centre is the centroid plus the normal of points 0 -> 1 over sqrt(z_last).
  const std::vector<Point2> points = {{0, 0}, {1, 0}, {2, 0}};
  const FittedCircle circle = hyper_circle_fit(points);
  EXPECT_DOUBLE_EQ(circle.center.x, 1.0);
  EXPECT_DOUBLE_EQ(circle.center.y, -1.0);  // (1,0) + (0, -(1 - 0)) / sqrt(1)
  EXPECT_TRUE(circle.on_a_line);
  EXPECT_FALSE(hyper_circle_fit(std::vector<Point2>{{0, 0}, {1, 0.1}, {2, 0}}).on_a_line);
}

TEST(FitConnect, HyperFitTakesTheDegenerateBranchOnlyForCollinearPointsAtEveryScale) {
  // D scales with the fourth power of the units: this arc's is 0.48 at scale 1 and 4.8e-25
  // at scale 1e-6, where the authors' absolute test (D < 1e-20) alone calls it a line.
  for (double scale : {1e-6, 1e-4, 1.0, 1e4}) {
    std::vector<Point2> arc;
    for (double t : {0.3, 0.5, 0.9, 1.4, 2.0}) arc.push_back(scale * Point2{2.0 + 3.0 * std::cos(t), -1.0 + 3.0 * std::sin(t)});
    const FittedCircle circle = hyper_circle_fit(arc);
    EXPECT_FALSE(circle.on_a_line) << "scale " << scale;
    EXPECT_NEAR(circle.radius / scale, 3.0, 1e-6) << "scale " << scale;
    const std::vector<Point2> line = {{0, 0}, {scale, 0}, {2 * scale, 0}};
    EXPECT_TRUE(hyper_circle_fit(line).on_a_line) << "scale " << scale;
  }
}

TEST(FitConnect, EdgesDoNotDependOnTheInputsUnits) {
  // 2 000 samples of a circle, each coordinate moved by up to half their spacing: at scale
  // 1e-4 a fit's neighbourhood is about 1e-7 units wide and 1e-6 long, and the absolute test
  // alone took such fits for lines.
  const std::vector<Point2> points = jittered(testing::uniform_circle(2000), 0.5 * 2 * std::numbers::pi / 2000, 7);
  const std::vector<Edge> edges = fitconnect(points).edges;
  for (double scale : {1e-4, 1e4}) {
    std::vector<Point2> scaled = points;
    for (Point2& p : scaled) p = scale * p;
    EXPECT_EQ(fitconnect(scaled).edges, edges) << "scale " << scale;
  }
}

TEST(FitConnect, TheBlendLeavesSamplesWhoseFitIsALineWhereTheyAre) {
  // Every side of the square holds samples whose neighbourhoods lie on it: their fits take
  // the degenerate branch, and blending onto its fallback circle (about a unit off the side)
  // would move them off the square.
  std::vector<Point2> square;
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < 25; ++k) {
      const double t = -1.0 + 0.08 * k;
      const Point2 along[4] = {{t, -1.0}, {1.0, t}, {-t, 1.0}, {-1.0, -t}};
      square.push_back(along[side]);
    }
  }
  const FittedNeighborhoods fits = connect_fitted_neighborhoods(square);
  const std::vector<Point2> moved = blended_positions(square, fits);
  int on_lines = 0;
  for (std::size_t i = 0; i < square.size(); ++i) {
    if (fits.states[i] != SampleState::Manifold || !fits.fits_on_a_line[i]) continue;
    ++on_lines;
    EXPECT_EQ(moved[i], square[i]) << i;
  }
  EXPECT_GT(on_lines, 40);
}

TEST(FitConnect, TheBlendLeavesALineCollinearUpToRoundingWhereItIs) {
  // y = 0.37 x + 1.5 at random x: collinear only up to rounding, so the exact test of the
  // skeleton does not see a line and the fits do not all take the degenerate branch; their
  // circles are made of rounding errors, and the authors' blend moves samples by whole units.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> x(-5.0, 5.0);
  std::vector<Point2> line;
  for (int i = 0; i < 30; ++i) {
    const double t = x(rng);
    line.push_back({t, 0.37 * t + 1.5});
  }
  ASSERT_FALSE(all_collinear(line));
  const FittedNeighborhoods fits = connect_fitted_neighborhoods(line);
  ASSERT_FALSE(fits.edges.empty());
  EXPECT_EQ(blended_positions(line, fits), line);
}

TEST(FitConnect, FewerThanThreePointsGiveNoEdgesAndUnmovedPositions) {
  for (int n = 0; n < 3; ++n) {
    std::vector<Point2> points;
    for (int i = 0; i < n; ++i) points.push_back({1.0 * i, 0.5 * i * i});
    const DenoisedCurve curve = fitconnect(points);
    EXPECT_TRUE(curve.edges.empty());
    EXPECT_EQ(curve.positions, points);
  }
}

TEST(FitConnect, NoisyCircleGivesTheExactPolygon) {
  // Spec 4: radius 1, 100 uniform samples, +-2 % noise per coordinate.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const std::vector<Point2> points = jittered(testing::uniform_circle(100), 0.02, seed);
    EXPECT_EQ(fitconnect(points).edges, cycle_edges(100)) << "seed " << seed;
  }
}

TEST(FitConnect, TwoDisjointNoisyCirclesGiveTwoPolygons) {
  std::vector<Point2> points = testing::uniform_circle(60);
  for (Point2 p : testing::uniform_circle(60)) points.push_back({p.x + 3.0, p.y});
  points = jittered(points, 0.01, 3);
  std::vector<Edge> expected = cycle_edges(60);
  for (Edge e : cycle_edges(60, 60)) expected.push_back(e);
  EXPECT_EQ(fitconnect(points).edges, sorted(expected));
}

// A unit circle sampled at spacing s, with a wider gap of 1.5 s before sample a (at angle 0)
// and one extra sample b at angle -0.2 s inside that gap: b's two nearest neighbours, a and
// a's successor, lie on one side of it, so its first fit is NONCONFORM (spec 4).
std::vector<Point2> circle_with_close_pair(int regular, int b_index) {
  const double s = 2 * std::numbers::pi / (regular + 0.5);
  std::vector<Point2> points;
  for (int k = 0; k < regular; ++k) points.push_back({std::cos(k * s), std::sin(k * s)});
  points.insert(points.begin() + b_index, Point2{std::cos(-0.2 * s), std::sin(-0.2 * s)});
  return points;
}

TEST(FitConnect, CloseSampleAfterItsTwinIsRemovedAsRedundant) {
  // b's index exceeds those of a and of c (the sample across the gap): a is visited first in
  // the second pass, grows, links over b to c, and b, still open inside both
  // neighbourhoods, is eliminated (spec 4, steps 3c and 3e).
  const int regular = 30, b = regular;  // a = 0, c = regular - 1
  const DenoisedCurve curve = fitconnect(circle_with_close_pair(regular, b));
  EXPECT_EQ(degrees_of(curve.edges, regular + 1)[b], 0);
  EXPECT_EQ(curve.edges, cycle_edges(regular));
}

TEST(FitConnect, CloseSampleBeforeItsTwinStaysConnected) {
  // Reordered so that b comes first: the rule does not fire and b joins the polygon between
  // c and a.
  const int regular = 30;
  const std::vector<Point2> points = circle_with_close_pair(regular, 0);  // b = 0, a = 1
  std::vector<Edge> expected = cycle_edges(regular + 1);                  // ..., c = 30, b = 0, a = 1, ...
  EXPECT_EQ(fitconnect(points).edges, expected);
}

TEST(FitConnect, RandomAngleCircleLeavesOnlyCloseSamplesUnconnected) {
  // Spec 4: random-angle samples leave a few percent unconnected (5.4 % over 30 x 200), and
  // most (91 %) of them have their two nearest neighbours on one side along the circle.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  int unconnected = 0, one_sided = 0, total = 0;
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> t(200);
    for (double& value : t) value = angle(rng);
    std::vector<Point2> points;
    for (double value : t) points.push_back({std::cos(value), std::sin(value)});
    const DenoisedCurve curve = fitconnect(points);
    const std::vector<int> degree = degrees_of(curve.edges, 200);
    for (int i = 0; i < 200; ++i) {
      EXPECT_LE(degree[i], 2);
      if (degree[i] != 0) continue;
      ++unconnected;
      // Signed angular offsets of the two nearest samples.
      int first = -1, second = -1;
      for (int j = 0; j < 200; ++j) {
        if (j == i) continue;
        const double d = distance(points[i], points[j]);
        if (first < 0 || d < distance(points[i], points[first])) {
          second = first;
          first = j;
        } else if (second < 0 || d < distance(points[i], points[second])) {
          second = j;
        }
      }
      auto offset = [&](int j) { return std::remainder(t[j] - t[i], 2 * std::numbers::pi); };
      one_sided += offset(first) * offset(second) > 0.0;
    }
    total += 200;
  }
  EXPECT_GT(unconnected, 0);
  EXPECT_LT(unconnected, total / 10);
  EXPECT_GE(one_sided, 0.75 * unconnected);
}

TEST(FitConnect, OpenArcIsAPathWithLeafEnds) {
  // Spec 4: noise-free open arc, correct with LEAF ends (they appear when growth is exhausted).
  const int n = 50;
  std::vector<Point2> points;
  for (int i = 0; i < n; ++i) {
    const double t = 0.8 * std::numbers::pi * i / (n - 1);
    points.push_back({2.0 * std::cos(t), 2.0 * std::sin(t)});
  }
  EXPECT_EQ(fitconnect(points).edges, path_edges(n));
  const FittedNeighborhoods uncapped = connect_fitted_neighborhoods(points, 0);
  EXPECT_EQ(uncapped.edges, path_edges(n));
  EXPECT_EQ(uncapped.states[0], SampleState::Leaf);
  EXPECT_EQ(uncapped.states[n - 1], SampleState::Leaf);
}

TEST(FitConnect, StateIsConsistentWithTheEdges) {
  // The per-point state pass 2 of StretchDenoise reads: every MANIFOLD point has two links
  // that reciprocate, the sides partition the neighbourhood and hold the links, and the
  // residual bounds every fitted point's distance to the fitted circle.
  const std::vector<Point2> points = jittered(testing::uniform_circle(100), 0.02, 4);
  const FittedNeighborhoods fits = connect_fitted_neighborhoods(points);
  ASSERT_EQ(fits.edges, cycle_edges(100));
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(fits.states[i], SampleState::Manifold) << i;
    for (int t = 0; t < 2; ++t) {
      const int q = fits.links[i][t];
      ASSERT_GE(q, 0);
      EXPECT_TRUE(fits.links[q][0] == i || fits.links[q][1] == i) << i;
      const auto side = fits.side(i, t);
      EXPECT_NE(std::find(side.begin(), side.end(), q), side.end()) << "link " << t << " of " << i;
    }
    EXPECT_EQ(fits.side(i, 0).size() + fits.side(i, 1).size(), fits.neighborhoods[i].size());
    EXPECT_NEAR(norm(fits.normals[i]), 1.0, 1e-12);
    EXPECT_LE(std::fabs(distance(points[i], fits.centers[i]) - fits.radii[i]), fits.residuals[i]);
    for (int q : fits.neighborhoods[i])
      EXPECT_LE(std::fabs(distance(points[q], fits.centers[i]) - fits.radii[i]), fits.residuals[i] + 1e-15);
  }
}

TEST(FitConnect, GrowthCapChangesOnlyWhatTheCappedSamplesWouldHaveLinked) {
  // README: the default cap is unbounded growth up to 4097 sites. A small cap keeps the edges
  // of a noisy closed curve, whose samples all resolve early, but not those of an open arc of
  // three quarters of a circle: its ends grow until they reach each other across the gap and
  // close it (edge 0 - (n - 1)), which a cap of 64 neighbours stops.
  const std::vector<Point2> circle = jittered(testing::uniform_circle(500), 0.005, 1);
  EXPECT_EQ(connect_fitted_neighborhoods(circle, 64).edges, connect_fitted_neighborhoods(circle, 0).edges);
  const int n = 300;
  std::vector<Point2> arc;
  for (int i = 0; i < n; ++i) {
    const double t = 1.5 * std::numbers::pi * i / (n - 1);
    arc.push_back({std::cos(t), std::sin(t)});
  }
  std::vector<Edge> closed = path_edges(n);
  closed.push_back(make_edge(0, n - 1));
  EXPECT_EQ(connect_fitted_neighborhoods(arc, 0).edges, sorted(closed));
  EXPECT_EQ(fitconnect(arc).edges, sorted(closed));
  EXPECT_EQ(connect_fitted_neighborhoods(arc, 64).edges, path_edges(n));
}

TEST(FitConnect, SquareIsExact) {
  // Spec 4: right-angled corners are reconstructed exactly.
  for (int n : {30, 40, 41, 60}) {
    const std::vector<Point2> square = testing::sample_polygon_evenly({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, n);
    EXPECT_EQ(fitconnect(square).edges, cycle_edges(n)) << n << " samples";
  }
}

TEST(FitConnect, SharpApexIsKeptOrCutByOneEdge) {
  // Spec 4: 25-60 degree apexes are mostly cut by an edge skipping 1-9 samples. The 45 degree
  // apexes of a right-isosceles triangle: the output is still one closed polygon, in order.
  const int n = 41;
  const std::vector<Point2> triangle = testing::sample_polygon_evenly({{0, 0}, {1, 0}, {0, 1}}, n);
  const std::vector<Edge> edges = fitconnect(triangle).edges;
  const std::vector<int> degree = degrees_of(edges, n);
  std::vector<int> kept;
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(degree[i] == 0 || degree[i] == 2) << "sample " << i;
    if (degree[i] == 2) kept.push_back(i);
  }
  const int m = static_cast<int>(kept.size());
  EXPECT_GE(m, n - 2 * 9);
  std::vector<Edge> polygon;
  for (int k = 0; k < m; ++k) polygon.push_back(make_edge(kept[k], kept[(k + 1) % m]));
  EXPECT_EQ(edges, sorted(polygon));
}

TEST(FitConnect, OpenRightAngleIsOnePathWithLeafEnds) {
  // Spec 4: an open L; the corner may be cut by an edge, the ends are LEAF.
  std::vector<Point2> points;
  for (int i = 20; i > 0; --i) points.push_back({0.0, 0.05 * i});
  for (int i = 0; i <= 20; ++i) points.push_back({0.05 * i, 0.0});
  const int n = static_cast<int>(points.size());
  const DenoisedCurve curve = fitconnect(points);
  const std::vector<int> degree = degrees_of(curve.edges, n);
  EXPECT_EQ(degree[0], 1);
  EXPECT_EQ(degree[n - 1], 1);
  int ends = 0, isolated = 0;
  for (int d : degree) {
    EXPECT_LE(d, 2);
    ends += d == 1;
    isolated += d == 0;
  }
  EXPECT_EQ(ends, 2);
  EXPECT_LE(isolated, 9);  // spec 4: a cut skips a few samples
  EXPECT_EQ(static_cast<int>(curve.edges.size()), n - isolated - 1);
}

double mean_distance_to_unit_circle(const std::vector<Point2>& points) {
  double sum = 0;
  for (Point2 p : points) sum += std::fabs(norm(p) - 1.0);
  return sum / static_cast<double>(points.size());
}

TEST(FitConnect, BlendMovesNoisySamplesTowardsTheCircle) {
  // Radial Gaussian noise of 0.05 and 0.1 of the radius (the local feature size of a circle).
  for (double noise : {0.05, 0.1}) {
    std::mt19937 rng(7);
    std::normal_distribution<double> radial(0.0, noise);
    std::vector<Point2> points = testing::uniform_circle(200);
    for (Point2& p : points) p = (1.0 + radial(rng)) * p;
    const DenoisedCurve curve = fitconnect(points);
    EXPECT_LT(mean_distance_to_unit_circle(curve.positions), 0.7 * mean_distance_to_unit_circle(points))
        << "noise " << noise;
    EXPECT_EQ(fitconnect(points, false).positions, points);  // mode "none"
  }
}

Point2 unit_normal_of_ellipse(double t) {
  const Point2 gradient{std::cos(t), 2 * std::sin(t)};  // of x^2 / 4 + y^2 at (2 cos t, sin t)
  return (1.0 / norm(gradient)) * gradient;
}

TEST(FitConnect, BlendMovesNoisyEllipseSamplesTowardsTheEllipse) {
  // Ellipse x = 2 cos t, y = sin t: local feature size 0.5 (the smallest radius of curvature);
  // noise along the normal of 0.05 and 0.1 of it, 800 samples. Distance to the ellipse by
  // dense sampling.
  std::vector<Point2> dense;
  for (int k = 0; k < 8000; ++k) {
    const double t = 2 * std::numbers::pi * k / 8000;
    dense.push_back({2 * std::cos(t), std::sin(t)});
  }
  auto distance_to_ellipse = [&](Point2 p) {
    double best = INFINITY;
    for (Point2 q : dense) best = std::min(best, distance(p, q));
    return best;
  };
  for (double noise : {0.05, 0.1}) {
    std::mt19937 rng(9);
    std::normal_distribution<double> along_normal(0.0, noise * 0.5);
    std::vector<Point2> points;
    for (int k = 0; k < 800; ++k) {
      const double t = 2 * std::numbers::pi * k / 800;
      const Point2 normal = unit_normal_of_ellipse(t);
      points.push_back(Point2{2 * std::cos(t), std::sin(t)} + along_normal(rng) * normal);
    }
    const DenoisedCurve curve = fitconnect(points);
    double before = 0, after = 0;
    for (int i = 0; i < 800; ++i) {
      before += distance_to_ellipse(points[i]);
      after += distance_to_ellipse(curve.positions[i]);
    }
    EXPECT_LT(after, 0.8 * before) << "noise " << noise;
  }
}


// The order of spec 2.2 computed the straightforward way, as the authors do (atan2 of every
// neighbour about the centre relative to the site, wrapped once, stable sort of the list):
// the fast path (angular_order.h) must give exactly this.
struct StraightforwardSides {
  std::vector<int> order;  // indices into the neighbours, ascending angle
  int negative = 0;
};
StraightforwardSides straightforward_sides(Point2 center, Point2 site, const std::vector<Point2>& neighbors) {
  const double own = std::atan2(site.y - center.y, site.x - center.x);
  std::vector<std::pair<double, int>> angles;
  for (int j = 0; j < static_cast<int>(neighbors.size()); ++j) {
    double theta = std::atan2(neighbors[j].y - center.y, neighbors[j].x - center.x) - own;
    if (theta < -std::numbers::pi) theta += 2 * std::numbers::pi;
    else if (theta > std::numbers::pi) theta -= 2 * std::numbers::pi;
    angles.push_back({theta, j});
  }
  std::stable_sort(angles.begin(), angles.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  StraightforwardSides sides;
  for (const auto& [theta, j] : angles) {
    sides.order.push_back(j);
    if (theta < 0) ++sides.negative;
  }
  return sides;
}

TEST(FitConnect, AngularOrderEqualsTheStraightforwardSortOnRandomAndTiedNeighbourhoods) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> size(1, 60);
  int ties_seen = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Point2 center{unit(rng), unit(rng)};
    const double scale = std::pow(10.0, 3 * unit(rng));  // 1e-3 .. 1e3
    const Point2 site = center + scale * Point2{unit(rng), unit(rng)};
    const int k = size(rng);
    std::vector<Point2> neighbors;
    for (int j = 0; j < k; ++j) {
      const int kind = trial % 7 == 0 ? j % 6 : 0;  // some neighbourhoods full of exact and near ties
      const Point2 u = site - center;
      Point2 q;
      switch (kind) {
        case 1: q = center + (1.0 + j) * u; break;                               // on the site's ray: theta = 0
        case 2: q = center - (0.5 + j) * u; break;                               // opposite: theta = +-pi
        case 3: q = neighbors.empty() ? site : center + 2.0 * (neighbors.back() - center); break;  // same ray as the last
        case 4: q = center; break;                                               // at the centre
        case 5: q = center + Point2{u.y, -u.x}; break;                           // theta = -pi/2, repeated
        default: q = center + scale * Point2{unit(rng), unit(rng)};
      }
      if (kind != 0) ++ties_seen;
      neighbors.push_back(q);
    }
    const StraightforwardSides expected = straightforward_sides(center, site, neighbors);
    // Guesses: none, the answer, its reverse, a shuffle, a partial list with a bogus entry.
    std::vector<std::vector<int>> guesses(5);
    guesses[1] = expected.order;
    guesses[2].assign(expected.order.rbegin(), expected.order.rend());
    guesses[3] = expected.order;
    std::shuffle(guesses[3].begin(), guesses[3].end(), rng);
    guesses[4].assign(expected.order.begin(), expected.order.begin() + k / 2);
    guesses[4].push_back(k + 3);
    for (std::vector<int>& order : guesses) {
      const int negative = sort_by_angle_about(center, site, neighbors, order);
      ASSERT_EQ(order, expected.order) << "trial " << trial;
      ASSERT_EQ(negative, expected.negative) << "trial " << trial;
    }
  }
  EXPECT_GT(ties_seen, 1000);
}

// Every stored neighbourhood of a finished run, re-sorted the straightforward way about its
// stored centre, gives its stored sides: the fast ordering changed nothing, growth step by
// growth step, on noisy closed curves, open arcs, corners and close pairs.
TEST(FitConnect, StoredSidesEqualTheStraightforwardSortOnManyInputs) {
  std::vector<std::vector<Point2>> inputs;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    inputs.push_back(jittered(testing::uniform_circle(150), 0.01 * seed, seed));
    inputs.push_back(jittered(testing::random_arc(120, 1.5 * std::numbers::pi, seed), 0.004 * (seed - 1), seed));
    inputs.push_back(jittered(testing::sample_polygon_evenly(testing::star_polygon(0.45), 200), 0.002 * seed, seed));
    inputs.push_back(circle_with_close_pair(40, static_cast<int>(seed) * 6));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
    std::vector<Point2> random_angles;
    for (int i = 0; i < 200; ++i) {
      const double t = angle(rng);
      random_angles.push_back({std::cos(t), std::sin(t)});
    }
    inputs.push_back(random_angles);
  }
  int checked = 0;
  for (std::size_t input = 0; input < inputs.size(); ++input) {
    const std::vector<Point2>& points = inputs[input];
    const FittedNeighborhoods fits = connect_fitted_neighborhoods(points, 0);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      const std::vector<int>& stored = fits.neighborhoods[i];
      if (stored.empty() || !std::isfinite(fits.centers[i].x) || !std::isfinite(fits.centers[i].y)) continue;
      // The stored sets are prefixes of the neighbour list, ordered by squared distance, ties
      // by index (nearest_neighbors.h).
      auto squared = [&](int q) { return dot(points[q] - points[i], points[q] - points[i]); };
      std::vector<int> list = stored;
      std::sort(list.begin(), list.end(), [&](int a, int b) {
        return squared(a) < squared(b) || (squared(a) == squared(b) && a < b);
      });
      std::vector<Point2> neighbors;
      for (int q : list) neighbors.push_back(points[q]);
      const StraightforwardSides expected = straightforward_sides(fits.centers[i], points[i], neighbors);
      std::vector<int> sides;
      for (int j = expected.negative - 1; j >= 0; --j) sides.push_back(list[expected.order[j]]);
      for (std::size_t j = expected.negative; j < expected.order.size(); ++j) sides.push_back(list[expected.order[j]]);
      ASSERT_EQ(sides, stored) << "input " << input << " site " << i;
      ASSERT_EQ(fits.side0_sizes[i], expected.negative) << "input " << input << " site " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 3000);
}

}  // namespace
}  // namespace curvebench
