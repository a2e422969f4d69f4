// evaluate_reconstruction and its JSON on a hand-made ground truth: the unit square sampled
// at its corners and side midpoints, with its diagonals as medial axis.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "io/metrics_json.h"
#include "metrics/evaluate_reconstruction.h"
#include "metrics/oracle_l2_error.h"

namespace curvebench {
namespace {

// Samples counter-clockwise from (0, 0): corners at even indices, midpoints at odd ones.
const std::vector<Point2> kSamples{{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}};

std::vector<Edge> square_cycle() {
  std::vector<Edge> edges;
  for (int i = 0; i < 8; ++i) edges.push_back(make_edge(i, (i + 1) % 8));
  return edges;
}

GroundTruth unit_square_truth() {
  GroundTruth truth;
  truth.curves.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.5, 0.5, 0.5, 0.5}});
  for (int i = 0; i < 8; ++i) truth.samples.push_back({0, i / 8.0, 0.5});
  truth.edges = square_cycle();
  truth.medial_axis = {{{0.5, 0.5}, {0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}};
  truth.dominant_points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return truth;
}

TEST(EvaluateReconstruction, TheTrueAdjacencyScoresPerfectly) {
  Reconstruction perfect;
  perfect.curve_edges = square_cycle();
  perfect.medial_axis = MedialAxis{{{0.5, 0.5}, {0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.5, 0, 0, 0, 0}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}};
  perfect.dominant_points = std::vector<int>{0, 2, 4, 6};
  const ReconstructionMetrics m = evaluate_reconstruction(unit_square_truth(), kSamples, perfect);
  EXPECT_EQ(m.true_curves, 1);
  EXPECT_DOUBLE_EQ(oracle_l2_error(unit_square_truth(), kSamples), 0.0);
  EXPECT_DOUBLE_EQ(*m.l2_error, 0.0);
  EXPECT_DOUBLE_EQ(*m.hausdorff, 0.0);
  EXPECT_DOUBLE_EQ(*m.curve_recall, 1.0);
  EXPECT_TRUE(m.topology->manifold);
  EXPECT_EQ(m.topology->closed_components, 1);
  EXPECT_TRUE(m.edges->exact);
  EXPECT_DOUBLE_EQ(*m.medial_axis_hausdorff, 0.0);
  EXPECT_EQ(m.dominant_points->count, 4);
  EXPECT_DOUBLE_EQ(*m.dominant_points->compression_ratio, 2.0);
  EXPECT_DOUBLE_EQ(*m.dominant_points->integral_square_error, 0.0);
}

TEST(EvaluateReconstruction, AMissingEdgeLeavesAnOpenCurveWithNoArea) {
  Reconstruction open;
  open.curve_edges = square_cycle();
  open.curve_edges->pop_back();  // drop [0, 7]
  const ReconstructionMetrics m = evaluate_reconstruction(unit_square_truth(), kSamples, open);
  EXPECT_DOUBLE_EQ(*m.l2_error, 1.0);
  // The open curve lies on the square, but the gap's middle (0, 0.25) is 0.25 from it.
  EXPECT_NEAR(*m.hausdorff, 0.25 / std::sqrt(2.0), 1e-4);
  // The gap, 0.5 long, is covered within the tolerance (0.01 of the diagonal) of its two ends.
  const double tolerance = kCurveRecallToleranceOverDiagonal * std::sqrt(2.0);
  EXPECT_DOUBLE_EQ(*m.curve_recall_tolerance, kCurveRecallToleranceOverDiagonal);  // the samples lie on the square
  EXPECT_NEAR(*m.curve_recall, (3.5 + 2 * tolerance) / 4.0, 1e-12);
  EXPECT_FALSE(m.topology->manifold);
  EXPECT_EQ(m.topology->dangling_vertices, 2);
  EXPECT_EQ(m.topology->closed_components, 0);
  EXPECT_FALSE(m.edges->exact);
  EXPECT_DOUBLE_EQ(m.edges->precision, 1.0);
  EXPECT_DOUBLE_EQ(m.edges->recall, 7.0 / 8.0);
  EXPECT_DOUBLE_EQ(m.edges->f1, 2 * (7.0 / 8.0) / (1 + 7.0 / 8.0));
  EXPECT_FALSE(m.medial_axis_hausdorff.has_value());
  EXPECT_FALSE(m.dominant_points.has_value());
}

TEST(EvaluateReconstruction, ANonInterpolatingCurveUsesItsOwnVertices) {
  Reconstruction shifted;
  shifted.new_curve = PolylineGraph{{{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}}, {{0, 1}, {1, 2}, {2, 3}, {0, 3}}};
  const ReconstructionMetrics m = evaluate_reconstruction(unit_square_truth(), kSamples, shifted);
  EXPECT_DOUBLE_EQ(*m.l2_error, 1.0);
  // Over the diagonal sqrt(2): the shift of 0.5.
  EXPECT_NEAR(*m.hausdorff, 0.5 / std::sqrt(2.0), 1e-5);
  EXPECT_TRUE(m.topology->manifold);
  // Within the tolerance t of it: the right halves of the bottom and the top, each with t
  // more at its left end, and t at each end of the right side (which its bottom and top
  // cross): 1 + 4 t of the length 4.
  const double tolerance = kCurveRecallToleranceOverDiagonal * std::sqrt(2.0);
  EXPECT_NEAR(*m.curve_recall, (1.0 + 4 * tolerance) / 4.0, 1e-12);
  EXPECT_FALSE(m.edges.has_value());  // its edges do not join samples
  // So the comparison with the true adjacency is null, not absent and not a number.
  const auto json = metrics_to_json(m);
  for (const char* key : {"exact", "edge_precision", "edge_recall", "edge_f1"}) {
    ASSERT_TRUE(json.contains(key)) << key;
    EXPECT_TRUE(json[key].is_null()) << key;
  }
  EXPECT_EQ(json["curve_recall"], *m.curve_recall);
}

TEST(OracleL2Error, MeasuresTheSamplingItself) {
  // A truth whose samples skip the corner (1, 1): joining them in true order cuts off the
  // triangle (1, 0.5), (1, 1), (0.5, 1) of area 1/8.
  GroundTruth truth = unit_square_truth();
  truth.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 5}, {5, 6}, {6, 7}, {0, 7}};
  EXPECT_DOUBLE_EQ(oracle_l2_error(truth, kSamples), 0.125);
}

TEST(EvaluateReconstruction, CurveRecallToleratesWhatTheSamplingItselfForces) {
  // Samples that skip the corner (1, 1): the true adjacency cuts it off, and the corner is
  // 0.5 / sqrt(2) from that chord, so the tolerance grows to it and the true adjacency
  // still recalls the whole curve.
  GroundTruth truth = unit_square_truth();
  truth.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 5}, {5, 6}, {6, 7}, {0, 7}};
  Reconstruction true_order;
  true_order.curve_edges = truth.edges;
  const ReconstructionMetrics m = evaluate_reconstruction(truth, kSamples, true_order);
  EXPECT_NEAR(*m.curve_recall_tolerance, 0.5 / std::sqrt(2.0) / std::sqrt(2.0), 2e-4);
  EXPECT_DOUBLE_EQ(*m.curve_recall, 1.0);
}

TEST(EvaluateReconstruction, MismatchedPointsAreRejected) {
  const std::vector<Point2> too_few(kSamples.begin(), kSamples.begin() + 7);
  EXPECT_THROW(evaluate_reconstruction(unit_square_truth(), too_few, Reconstruction{}), std::invalid_argument);
  EXPECT_THROW(oracle_l2_error(unit_square_truth(), too_few), std::invalid_argument);
  Reconstruction bad;
  bad.curve_edges = std::vector<Edge>{{0, 8}};
  EXPECT_THROW(evaluate_reconstruction(unit_square_truth(), kSamples, bad), std::out_of_range);
  Reconstruction not_finite;
  not_finite.medial_axis = MedialAxis{{{0.5, 0.5}, {NAN, 0}}, {0.5, 0}, {{0, 1}}};
  EXPECT_THROW(evaluate_reconstruction(unit_square_truth(), kSamples, not_finite), std::invalid_argument);
}

TEST(MetricsJson, AbsentOutputsHaveNoKeysAndInfiniteDistancesAreNull) {
  Reconstruction empty_curve;
  empty_curve.curve_edges = std::vector<Edge>{};
  const auto json = metrics_to_json(evaluate_reconstruction(unit_square_truth(), kSamples, empty_curve));
  EXPECT_EQ(json["l2_error"], 1.0);
  EXPECT_TRUE(json["hausdorff"].is_null());
  EXPECT_EQ(json["manifold"], false);
  EXPECT_EQ(json["edge_precision"], 0.0);
  EXPECT_EQ(json["edge_f1"], 0.0);
  EXPECT_EQ(json["curve_recall"], 0.0);
  EXPECT_FALSE(json.contains("medial_axis_hausdorff"));
  EXPECT_FALSE(json.contains("dominant_points"));
}

}  // namespace
}  // namespace curvebench
