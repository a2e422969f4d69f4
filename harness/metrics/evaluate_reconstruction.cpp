#include "metrics/evaluate_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include "metrics/curve_recall.h"
#include "metrics/hausdorff_distance.h"
#include "metrics/l2_error.h"
#include "metrics/segments.h"
#include "metrics/true_curve_segments.h"

namespace curvebench {
namespace {

// Hausdorff distances are exact to this fraction of the diagonal (hausdorff_distance.h).
constexpr double kHausdorffToleranceOverDiagonal = 1e-4;

double bounding_box_diagonal(const GroundTruth& truth) {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (const auto& curve : truth.curves) {
    for (const Point2 p : curve.vertices) {
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
  }
  return std::hypot(max_x - min_x, max_y - min_y);
}

// The edges of a graph, plus each vertex that has no edge as a point.
std::vector<Segment2> graph_segments(std::span<const Point2> vertices, std::span<const Edge> edges) {
  std::vector<Segment2> segments = edge_segments(vertices, edges);
  std::vector<bool> on_edge(vertices.size(), false);
  for (const Edge& e : edges) on_edge[e[0]] = on_edge[e[1]] = true;
  for (size_t v = 0; v < vertices.size(); ++v) {
    if (!on_edge[v]) segments.push_back({vertices[v], vertices[v]});
  }
  return segments;
}

}  // namespace

ReconstructionMetrics evaluate_reconstruction(const GroundTruth& truth, std::span<const Point2> points,
                                              const Reconstruction& reconstruction) {
  if (points.size() != truth.samples.size()) {
    throw std::invalid_argument("the points file has " + std::to_string(points.size()) + " points but the ground truth describes " +
                                std::to_string(truth.samples.size()) + " samples");
  }
  const std::vector<Segment2> true_curves = true_curve_segments(truth);
  const double diagonal = bounding_box_diagonal(truth);
  const double hausdorff_tolerance = kHausdorffToleranceOverDiagonal * diagonal;

  ReconstructionMetrics metrics;
  metrics.true_curves = static_cast<int>(truth.curves.size());
  const bool open_truth = has_open_curve(truth.curves);
  auto sampling_deviation = [&] {
    const std::vector<Segment2> true_order = edge_segments(points, truth.edges);
    // Plus the margin below the exact value that the distance may have, so that the true
    // adjacency always scores 1.
    return true_order.empty() ? 0.0 : hausdorff_distance(true_curves, true_order, hausdorff_tolerance) + hausdorff_tolerance;
  };

  if (const auto view = curve_view(reconstruction, points)) {
    const std::vector<Edge> edges(view->edges.begin(), view->edges.end());
    const std::vector<Segment2> curve = edge_segments(view->vertices, edges);
    require_finite(curve, "the reconstructed curve");
    metrics.l2_error = open_truth ? std::numeric_limits<double>::quiet_NaN() : l2_error(true_curves, curve);
    metrics.hausdorff = hausdorff_distance(true_curves, curve, hausdorff_tolerance) / diagonal;
    const double tolerance = std::max(kCurveRecallToleranceOverDiagonal * diagonal, sampling_deviation());
    metrics.curve_recall = curve_recall(true_curves, curve, tolerance);
    metrics.curve_recall_tolerance = tolerance / diagonal;
    metrics.topology = curve_topology(edges);
    std::vector<char> on_curve(view->vertices.size(), 0);
    for (const Edge& e : edges) on_curve[e[0]] = on_curve[e[1]] = 1;
    std::vector<Point2> curve_vertices;
    for (std::size_t v = 0; v < on_curve.size(); ++v) {
      if (on_curve[v]) curve_vertices.push_back(view->vertices[v]);
    }
    DistanceToCurve distance = distance_to_curve(true_curves, curve_vertices);
    metrics.vertex_distance = DistanceToCurve{distance.mean / diagonal, distance.max / diagonal};
    if (view->on_input_points) metrics.edges = edge_agreement(edges, truth.edges);
  }

  if (reconstruction.medial_axis && !open_truth) {
    const auto reconstructed = graph_segments(reconstruction.medial_axis->vertices, reconstruction.medial_axis->edges);
    require_finite(reconstructed, "the reconstructed medial axis");
    const auto expected = graph_segments(truth.medial_axis.vertices, truth.medial_axis.edges);
    metrics.medial_axis_hausdorff = hausdorff_distance(expected, reconstructed, hausdorff_tolerance) / diagonal;
  }

  if (reconstruction.dominant_points) {
    std::vector<int> curve_of_sample;
    std::vector<double> parameter_of_sample;
    for (const auto& sample : truth.samples) {
      curve_of_sample.push_back(sample.curve);
      parameter_of_sample.push_back(sample.parameter);
    }
    metrics.dominant_points = dominant_point_quality(points, curve_of_sample, parameter_of_sample, *reconstruction.dominant_points);
  }
  return metrics;
}

}  // namespace curvebench
