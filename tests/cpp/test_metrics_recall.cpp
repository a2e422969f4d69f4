// The topology-tolerant accuracy metrics: curve recall (the share of true length within a
// tolerance of the output) and edge F1, on hand-made cases with answers worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "metrics/curve_recall.h"
#include "metrics/edge_agreement.h"
#include "metrics/segments.h"

namespace curvebench {
namespace {

std::vector<Segment2> unit_square() { return closed_polyline_segments(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }

TEST(CurveRecall, TheCurveItselfIsFullyRecalled) { EXPECT_DOUBLE_EQ(curve_recall(unit_square(), unit_square(), 1e-3), 1.0); }

TEST(CurveRecall, AMissingSideCostsItsLengthLessTheTwoEndsWithinTheTolerance) {
  // Without the side from (0, 1) to (0, 0), that side is covered only within 0.1 of its two
  // ends (by the bottom and the top sides): 3 + 2 * 0.1 of the length 4.
  auto three_sides = unit_square();
  three_sides.pop_back();
  EXPECT_DOUBLE_EQ(curve_recall(unit_square(), three_sides, 0.1), 3.2 / 4.0);
  // L2 would call this curve empty (it encloses nothing); recall calls it mostly found.
}

TEST(CurveRecall, AParallelOffsetIsRecalledOnlyWithinTheTolerance) {
  const std::vector<Segment2> truth{{{0, 0}, {1, 0}}};
  const std::vector<Segment2> above{{{0, 0.05}, {1, 0.05}}};
  EXPECT_DOUBLE_EQ(curve_recall(truth, above, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(curve_recall(truth, above, 0.04), 0.0);
  // A shorter offset segment over [0.25, 0.5]: the disks at its ends reach
  // sqrt(0.1^2 - 0.05^2) farther along the truth on each side.
  const std::vector<Segment2> short_above{{{0.25, 0.05}, {0.5, 0.05}}};
  EXPECT_NEAR(curve_recall(truth, short_above, 0.1), 0.25 + 2 * std::sqrt(0.01 - 0.0025), 1e-12);
}

TEST(CurveRecall, APointCoversTheChordOfItsDisk) {
  // The point (0.5, 0.3) with tolerance 0.5 covers |x - 0.5| <= sqrt(0.25 - 0.09) = 0.4.
  const std::vector<Segment2> truth{{{0, 0}, {1, 0}}};
  const std::vector<Segment2> point{{{0.5, 0.3}, {0.5, 0.3}}};
  EXPECT_NEAR(curve_recall(truth, point, 0.5), 0.8, 1e-12);
}

TEST(CurveRecall, ACrossingSegmentCoversTheWidthOfItsBandAlongTheTruth) {
  const std::vector<Segment2> truth{{{0, 0}, {10, 0}}};
  const std::vector<Segment2> perpendicular{{{5, -1}, {5, 1}}};
  EXPECT_NEAR(curve_recall(truth, perpendicular, 0.5), 1.0 / 10.0, 1e-12);
  // At 45 degrees, |x - 5| / sqrt(2) <= 0.5: a width of sqrt(2).
  const std::vector<Segment2> diagonal{{{4, -1}, {6, 1}}};
  EXPECT_NEAR(curve_recall(truth, diagonal, 0.5), std::sqrt(2.0) / 10.0, 1e-12);
}

TEST(CurveRecall, OverlappingOutputIsCountedOnce) {
  auto twice = unit_square();
  for (const Segment2& s : unit_square()) twice.push_back({s.target, s.source});
  EXPECT_DOUBLE_EQ(curve_recall(unit_square(), twice, 0.01), 1.0);
  // Two overlapping halves of the bottom side, [0, 0.6] and [0.4, 1]: it is covered once.
  const std::vector<Segment2> truth{{{0, 0}, {1, 0}}};
  const std::vector<Segment2> halves{{{0, 0}, {0.6, 0}}, {{0.4, 0}, {1, 0}}};
  EXPECT_DOUBLE_EQ(curve_recall(truth, halves, 1e-6), 1.0);
}

TEST(CurveRecall, NothingRecallsNothingAndBadInputIsRefused) {
  EXPECT_DOUBLE_EQ(curve_recall(unit_square(), {}, 0.1), 0.0);
  EXPECT_THROW(curve_recall(unit_square(), unit_square(), 0.0), std::invalid_argument);
  const std::vector<Segment2> not_finite{{{0, 0}, {NAN, 1}}};
  EXPECT_THROW(curve_recall(unit_square(), not_finite, 0.1), std::invalid_argument);
  const std::vector<Segment2> no_length{{{1, 1}, {1, 1}}};
  EXPECT_THROW(curve_recall(no_length, unit_square(), 0.1), std::invalid_argument);
}

TEST(CurveRecall, ADenseCircleAgainstItsHalfIsHalf) {
  // 10^5 segments on each side: the grid keeps it fast, and half the circle is found.
  const int n = 100000;
  std::vector<Point2> circle;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    circle.push_back({std::cos(t), std::sin(t)});
  }
  const auto truth = closed_polyline_segments(circle);
  const std::vector<Segment2> half(truth.begin(), truth.begin() + n / 2);
  // The half covers its own length plus the tolerance at each of its two ends.
  const double tolerance = 1e-3;
  EXPECT_NEAR(curve_recall(truth, half, tolerance), (std::numbers::pi + 2 * tolerance) / (2 * std::numbers::pi), 1e-6);
}

TEST(EdgeF1, IsTheHarmonicMeanOfPrecisionAndRecall) {
  // Precision 2/3, recall 1/2: F1 = 2 (1/3) / (7/6) = 4/7.
  const std::vector<Edge> truth{{0, 1}, {1, 2}, {2, 3}, {0, 3}};
  const std::vector<Edge> found{{0, 1}, {1, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(edge_agreement(found, truth).f1, 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(edge_agreement(truth, truth).f1, 1.0);
  // No correct edge: precision and recall are 0, and so is F1 (not 0/0).
  const std::vector<Edge> wrong{{0, 2}, {1, 3}};
  EXPECT_DOUBLE_EQ(edge_agreement(wrong, truth).f1, 0.0);
  EXPECT_DOUBLE_EQ(edge_agreement({}, truth).f1, 0.0);
}

}  // namespace
}  // namespace curvebench
