// L2 error and even-odd regions on hand-made cases whose areas are known by hand.
#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "metrics/even_odd_areas.h"
#include "metrics/l2_error.h"
#include "metrics/segments.h"

namespace curvebench {
namespace {

// Axis-aligned square, counter-clockwise from its lower-left corner.
std::vector<Point2> square(double x, double y, double side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

std::vector<Segment2> square_segments(double x, double y, double side) { return closed_polyline_segments(square(x, y, side)); }

std::vector<Segment2> joined(std::vector<Segment2> a, const std::vector<Segment2>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(EvenOddAreas, SquareAgainstItselfDiffersNowhere) {
  const auto unit = square_segments(0, 0, 1);
  const EvenOddAreas areas = even_odd_areas(unit, unit);
  EXPECT_DOUBLE_EQ(areas.first, 1.0);
  EXPECT_DOUBLE_EQ(areas.second, 1.0);
  EXPECT_DOUBLE_EQ(areas.symmetric_difference, 0.0);
  EXPECT_DOUBLE_EQ(l2_error(unit, unit), 0.0);
}

TEST(EvenOddAreas, OrientationAndStartingVertexDoNotMatter) {
  std::vector<Point2> clockwise = square(0, 0, 2);
  std::reverse(clockwise.begin(), clockwise.end());
  std::rotate(clockwise.begin(), clockwise.begin() + 1, clockwise.end());
  EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 2), closed_polyline_segments(clockwise)), 0.0);
}

TEST(L2Error, UnitSquareShiftedByHalfItsSideIsOne) {
  // Overlap 1/2, symmetric difference 1/2 + 1/2 = 1, true area 1.
  EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 1), square_segments(0.5, 0, 1)), 1.0);
}

TEST(L2Error, DisjointReconstructionIsTwo) {
  EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 1), square_segments(5, 5, 1)), 2.0);
}

TEST(L2Error, EmptyReconstructionIsOne) { EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 1), {}), 1.0); }

TEST(L2Error, OpenPolylineHasNoAreaSoTheErrorIsOne) {
  // Three sides of the square: no closed curve, so the region is empty.
  const std::vector<Point2> corners = square(0, 0, 1);
  const std::vector<Segment2> three_sides{{corners[0], corners[1]}, {corners[1], corners[2]}, {corners[2], corners[3]}};
  const EvenOddAreas areas = even_odd_areas(square_segments(0, 0, 1), three_sides);
  EXPECT_DOUBLE_EQ(areas.second, 0.0);
  EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 1), three_sides), 1.0);
}

TEST(L2Error, DanglingEdgesAddNoArea) {
  // The square plus an edge poking inside, one poking outside and a loose one far away.
  const auto with_dangling = joined(square_segments(0, 0, 1), {{{0.5, 0}, {0.5, 0.7}},
                                                               {{1, 1}, {2, 2}},
                                                               {{5, 5}, {6, 5}}});
  EXPECT_DOUBLE_EQ(l2_error(square_segments(0, 0, 1), with_dangling), 0.0);
}

TEST(L2Error, BridgeBetweenTwoSquaresAddsNoArea) {
  const auto two = joined(square_segments(0, 0, 1), square_segments(3, 0, 1));
  const auto bridged = joined(two, {{{1, 0.5}, {3, 0.5}}});
  EXPECT_DOUBLE_EQ(l2_error(two, bridged), 0.0);
}

TEST(L2Error, SquareWithAHoleIsTheRing) {
  // 4x4 square with a 2x2 hole: true area 16 - 4 = 12.
  const auto ring = joined(square_segments(0, 0, 4), square_segments(1, 1, 2));
  EXPECT_DOUBLE_EQ(even_odd_areas(ring, {}).first, 12.0);
  EXPECT_DOUBLE_EQ(l2_error(ring, ring), 0.0);
  // Missing the hole: the reconstruction also covers the 4 of the hole.
  EXPECT_DOUBLE_EQ(l2_error(ring, square_segments(0, 0, 4)), 4.0 / 12.0);
  // Only the hole: 12 + 4 differ.
  EXPECT_DOUBLE_EQ(l2_error(ring, square_segments(1, 1, 2)), 16.0 / 12.0);
}

TEST(L2Error, TwoDisjointSquares) {
  const auto two = joined(square_segments(0, 0, 1), square_segments(2, 0, 1));
  EXPECT_DOUBLE_EQ(even_odd_areas(two, {}).first, 2.0);
  EXPECT_DOUBLE_EQ(l2_error(two, two), 0.0);
  // Finding only one of them misses half the true area.
  EXPECT_DOUBLE_EQ(l2_error(two, square_segments(0, 0, 1)), 0.5);
  // Joining them into one 3x1 rectangle adds the gap of area 1.
  EXPECT_DOUBLE_EQ(l2_error(two, closed_polyline_segments(std::vector<Point2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}})), 0.5);
}

TEST(EvenOddAreas, CrossingClosedPolylineFollowsTheEvenOddRule) {
  // A bow tie (two triangles meeting at (1, 1)): each triangle has area 1.
  const std::vector<Point2> bow_tie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  EXPECT_DOUBLE_EQ(even_odd_areas(closed_polyline_segments(bow_tie), {}).first, 2.0);
  // Two overlapping squares drawn as one edge set: the overlap has even depth, so it is out.
  const auto overlapping = joined(square_segments(0, 0, 2), square_segments(1, 1, 2));
  EXPECT_DOUBLE_EQ(even_odd_areas(overlapping, {}).first, 4.0 + 4.0 - 2.0 * 1.0);
}

TEST(EvenOddAreas, CoincidentBoundariesCancel) {
  // Two unit squares sharing a side: the shared side is covered twice and drops out, so the
  // region is the 2x1 rectangle.
  const auto adjacent = joined(square_segments(0, 0, 1), square_segments(1, 0, 1));
  EXPECT_DOUBLE_EQ(even_odd_areas(adjacent, {}).first, 2.0);
  // The same square given twice cancels completely.
  const auto twice = joined(square_segments(0, 0, 1), square_segments(0, 0, 1));
  EXPECT_DOUBLE_EQ(even_odd_areas(twice, {}).first, 0.0);
}

TEST(EvenOddAreas, BranchingVertexTakesTheLeastDepth) {
  // A square with one diagonal: both triangles touch the outside, so the whole square is in.
  const auto with_diagonal = joined(square_segments(0, 0, 1), {{{0, 0}, {1, 1}}});
  EXPECT_DOUBLE_EQ(even_odd_areas(with_diagonal, {}).first, 1.0);
}

TEST(EvenOddAreas, DenseCircleApproachesPi) {
  std::vector<Point2> circle;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    circle.push_back({std::cos(t), std::sin(t)});
  }
  const double inscribed_polygon_area = 0.5 * n * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(even_odd_areas(closed_polyline_segments(circle), {}).first, inscribed_polygon_area, 1e-12);
}

TEST(L2Error, TruthWithoutAreaIsRejected) {
  EXPECT_THROW(l2_error(std::vector<Segment2>{{{0, 0}, {1, 0}}}, square_segments(0, 0, 1)), std::invalid_argument);
}

TEST(EvenOddAreas, NonFiniteCoordinatesAreRejected) {
  const std::vector<Segment2> broken{{{0, 0}, {1, std::numeric_limits<double>::infinity()}}};
  EXPECT_THROW(even_odd_areas(square_segments(0, 0, 1), broken), std::invalid_argument);
}

TEST(Segments, EdgeOutsideThePointsIsRejected) {
  const std::vector<Point2> points{{0, 0}, {1, 0}};
  EXPECT_THROW(edge_segments(points, std::vector<Edge>{{0, 2}}), std::out_of_range);
}

}  // namespace
}  // namespace curvebench
