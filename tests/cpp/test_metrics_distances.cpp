// Hausdorff distance, topology, edge agreement and dominant-point measures on hand-made
// cases with answers worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "metrics/curve_topology.h"
#include "metrics/dominant_point_quality.h"
#include "metrics/edge_agreement.h"
#include "metrics/hausdorff_distance.h"
#include "metrics/segments.h"

namespace curvebench {
namespace {

std::vector<Segment2> unit_square() { return closed_polyline_segments(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }

TEST(HausdorffDistance, IdenticalSetsAreAtZero) { EXPECT_DOUBLE_EQ(hausdorff_distance(unit_square(), unit_square(), 0.01), 0.0); }

TEST(HausdorffDistance, ShiftedSquareIsAtTheShift) {
  const auto shifted = closed_polyline_segments(std::vector<Point2>{{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}});
  EXPECT_DOUBLE_EQ(hausdorff_distance(unit_square(), shifted, 0.01), 0.5);
}

TEST(HausdorffDistance, TheLargerDirectedDistanceWins) {
  // From the post to the base: its top (0.5, 2) is 2 away. From the base to the post: its
  // ends are hypot(0.5, 1) away. The symmetric distance is the larger, 2.
  const std::vector<Segment2> base{{{0, 0}, {1, 0}}};
  const std::vector<Segment2> post{{{0.5, 1}, {0.5, 2}}};
  EXPECT_DOUBLE_EQ(hausdorff_distance(base, post, 0.01), 2.0);
}

TEST(HausdorffDistance, DistancesAreToSegmentsNotToTheirEnds) {
  // A point above the middle of a long segment: from the point to the segment it is 1 (to
  // the segment's interior); from the segment to the point it is hypot(1, 1) (its ends).
  const std::vector<Segment2> segment{{{-1, 0}, {1, 0}}};
  const std::vector<Segment2> point{{{0, 1}, {0, 1}}};
  EXPECT_DOUBLE_EQ(hausdorff_distance(segment, point, 0.7), std::hypot(1.0, 1.0));
  // A V over the base: the apex (0, 1) is 1 from the base's interior, which is attained
  // because the apex is a segment end and always sampled.
  const std::vector<Segment2> vee{{{-1, 0}, {0, 1}}, {{0, 1}, {1, 0}}};
  EXPECT_DOUBLE_EQ(hausdorff_distance(segment, vee, 0.3), 1.0);
}

TEST(HausdorffDistance, TheFarthestPointInsideASegmentIsFound) {
  // A segment against its two end points: the exact answer, 0.5, is at the midpoint, where
  // neither set has a vertex. The result is never above it and at most the tolerance below.
  const std::vector<Segment2> segment{{{0, 0}, {1, 0}}};
  const std::vector<Segment2> ends{{{0, 0}, {0, 0}}, {{1, 0}, {1, 0}}};
  for (double tolerance : {0.3, 0.1, 1e-3, 1e-7}) {
    const double found = hausdorff_distance(segment, ends, tolerance);
    EXPECT_LE(found, 0.5);
    EXPECT_GE(found, 0.5 - tolerance);
  }
  // A chord of the unit circle against the circle drawn finely: the farthest point is the
  // chord's middle, at the sagitta 1 - cos(pi / 8) from the arc.
  std::vector<Segment2> arc;
  const int pieces = 20000;
  for (int k = 0; k < pieces; ++k) {
    const double t0 = (std::numbers::pi / 4) * k / pieces, t1 = (std::numbers::pi / 4) * (k + 1) / pieces;
    arc.push_back({{std::cos(t0), std::sin(t0)}, {std::cos(t1), std::sin(t1)}});
  }
  const std::vector<Segment2> chord{{{1, 0}, {std::cos(std::numbers::pi / 4), std::sin(std::numbers::pi / 4)}}};
  EXPECT_NEAR(hausdorff_distance(arc, chord, 1e-7), 1 - std::cos(std::numbers::pi / 8), 2e-7);
}

TEST(HausdorffDistance, EmptySetIsInfinitelyFar) {
  EXPECT_EQ(hausdorff_distance(unit_square(), {}, 0.1), std::numeric_limits<double>::infinity());
}

TEST(HausdorffDistance, NonFiniteCoordinatesAreRejected) {
  const std::vector<Segment2> broken{{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}}};
  EXPECT_THROW(hausdorff_distance(unit_square(), broken, 0.1), std::invalid_argument);
}

TEST(HausdorffDistance, ManySegmentsUseTheGridCorrectly) {
  // A fine staircase against a straight diagonal: every stair corner is 1/(2n)*sqrt(2) off.
  const int n = 500;
  std::vector<Segment2> stairs;
  for (int k = 0; k < n; ++k) {
    const double a = static_cast<double>(k) / n;
    const double b = static_cast<double>(k + 1) / n;
    stairs.push_back({{a, a}, {b, a}});
    stairs.push_back({{b, a}, {b, b}});
  }
  const std::vector<Segment2> diagonal{{{0, 0}, {1, 1}}};
  EXPECT_NEAR(hausdorff_distance(stairs, diagonal, 1e-4), std::sqrt(0.5) / n, 1e-12);
}

TEST(CurveTopology, TwoClosedCurvesAreAManifold) {
  const std::vector<Edge> edges{{0, 1}, {1, 2}, {0, 2}, {3, 4}, {4, 5}, {5, 6}, {3, 6}};
  const CurveTopology t = curve_topology(edges);
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.closed_components, 2);
  EXPECT_EQ(t.dangling_vertices, 0);
  EXPECT_EQ(t.branching_vertices, 0);
}

TEST(CurveTopology, OpenChainAndBranchAreNotAManifold) {
  // A triangle with a tail (vertex 0 branches, vertex 4 dangles) and a separate open chain.
  const std::vector<Edge> edges{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {3, 4}, {7, 8}, {8, 9}};
  const CurveTopology t = curve_topology(edges);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.closed_components, 0);
  EXPECT_EQ(t.dangling_vertices, 3);
  EXPECT_EQ(t.branching_vertices, 1);
}

TEST(CurveTopology, NoEdgesIsNotAManifold) {
  const CurveTopology t = curve_topology({});
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 0);
}

TEST(EdgeAgreement, SameSetInAnyOrderIsExact) {
  const std::vector<Edge> truth{{0, 1}, {1, 2}, {0, 2}};
  const std::vector<Edge> found{{2, 1}, {2, 0}, {1, 0}, {0, 1}};
  const EdgeAgreement a = edge_agreement(found, truth);
  EXPECT_TRUE(a.exact);
  EXPECT_DOUBLE_EQ(a.precision, 1.0);
  EXPECT_DOUBLE_EQ(a.recall, 1.0);
}

TEST(EdgeAgreement, PrecisionAndRecallCountCorrectEdges) {
  const std::vector<Edge> truth{{0, 1}, {1, 2}, {2, 3}, {0, 3}};
  const std::vector<Edge> found{{0, 1}, {1, 2}, {0, 2}};
  const EdgeAgreement a = edge_agreement(found, truth);
  EXPECT_FALSE(a.exact);
  EXPECT_EQ(a.correct_edges, 2);
  EXPECT_DOUBLE_EQ(a.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(a.recall, 2.0 / 4.0);
  const EdgeAgreement empty = edge_agreement({}, truth);
  EXPECT_DOUBLE_EQ(empty.precision, 0.0);
  EXPECT_DOUBLE_EQ(empty.recall, 0.0);
}

// Eight samples around the unit square: the four corners and the four side midpoints
// pushed outwards by 0.1, in counter-clockwise order from (0, 0).
struct SquareSamples {
  std::vector<Point2> points{{0, 0}, {0.5, -0.1}, {1, 0}, {1.1, 0.5}, {1, 1}, {0.5, 1.1}, {0, 1}, {-0.1, 0.5}};
  std::vector<int> curve = std::vector<int>(8, 0);
  std::vector<double> parameter{0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875};
};

TEST(DominantPointQuality, CornersOfASquare) {
  const SquareSamples s;
  const DominantPointQuality q = dominant_point_quality(s.points, s.curve, s.parameter, std::vector<int>{0, 2, 4, 6});
  EXPECT_EQ(q.count, 4);
  EXPECT_DOUBLE_EQ(*q.compression_ratio, 8.0 / 4.0);
  EXPECT_NEAR(*q.integral_square_error, 4 * 0.01, 1e-15);  // four midpoints, 0.1 off each side
  EXPECT_NEAR(*q.figure_of_merit, 2.0 / 0.04, 1e-9);
}

TEST(DominantPointQuality, OrderIsTheCurveOrderNotTheIndexOrder) {
  // The same samples listed in a shuffled file order give the same measures.
  const SquareSamples s;
  const std::vector<int> order{5, 2, 7, 0, 3, 6, 1, 4};
  std::vector<Point2> points;
  std::vector<double> parameter;
  std::vector<int> dominant;
  for (int i = 0; i < 8; ++i) {
    points.push_back(s.points[order[i]]);
    parameter.push_back(s.parameter[order[i]]);
    if (order[i] % 2 == 0) dominant.push_back(i);
  }
  const DominantPointQuality q = dominant_point_quality(points, s.curve, parameter, dominant);
  EXPECT_NEAR(*q.integral_square_error, 0.04, 1e-15);
}

TEST(DominantPointQuality, TwoOppositeCornersMeasureAgainstTheDiagonal) {
  const SquareSamples s;
  const DominantPointQuality q = dominant_point_quality(s.points, s.curve, s.parameter, std::vector<int>{0, 4});
  // Distances to the diagonal y = x: corners (1,0), (0,1) at 1/sqrt2 (squared 0.5); the
  // midpoints (0.5,-0.1) etc. at 0.6/sqrt2 (squared 0.18).
  EXPECT_NEAR(*q.integral_square_error, 2 * 0.5 + 4 * 0.18, 1e-12);
  EXPECT_DOUBLE_EQ(*q.compression_ratio, 4.0);
}

TEST(DominantPointQuality, OutliersAndMissingCurves) {
  SquareSamples s;
  s.points.push_back({5, 5});
  s.curve.push_back(-1);
  s.parameter.push_back(std::numeric_limits<double>::quiet_NaN());
  // An outlier reported as dominant counts but joins no polygon.
  const DominantPointQuality with_outlier = dominant_point_quality(s.points, s.curve, s.parameter, std::vector<int>{0, 2, 4, 6, 8});
  EXPECT_EQ(with_outlier.count, 5);
  EXPECT_DOUBLE_EQ(*with_outlier.compression_ratio, 9.0 / 5.0);
  EXPECT_NEAR(*with_outlier.integral_square_error, 0.04, 1e-15);
  // A curve without dominant points has no polygon: ISE and FOM are absent.
  const DominantPointQuality only_outlier = dominant_point_quality(s.points, s.curve, s.parameter, std::vector<int>{8});
  EXPECT_EQ(only_outlier.count, 1);
  EXPECT_FALSE(only_outlier.integral_square_error.has_value());
  EXPECT_FALSE(only_outlier.figure_of_merit.has_value());
  // No dominant points at all: no ratio either.
  const DominantPointQuality none = dominant_point_quality(s.points, s.curve, s.parameter, {});
  EXPECT_EQ(none.count, 0);
  EXPECT_FALSE(none.compression_ratio.has_value());
}

TEST(DominantPointQuality, ExactPolygonHasNoFigureOfMerit) {
  // Samples exactly on the sides: ISE is 0, and CR / 0 is not reported.
  const std::vector<Point2> points{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<int> curve(5, 0);
  const std::vector<double> parameter{0, 0.1, 0.2, 0.5, 0.8};
  const DominantPointQuality q = dominant_point_quality(points, curve, parameter, std::vector<int>{0, 2, 3, 4});
  EXPECT_DOUBLE_EQ(*q.integral_square_error, 0.0);
  EXPECT_FALSE(q.figure_of_merit.has_value());
}

}  // namespace
}  // namespace curvebench
