#include "io/metrics_json.h"

#include <cmath>

namespace curvebench {
namespace {

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json number_or_null(const std::optional<double>& value) {
  return value ? number_or_null(*value) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json metrics_to_json(const ReconstructionMetrics& metrics) {
  nlohmann::ordered_json json;
  json["true_curves"] = metrics.true_curves;
  if (metrics.l2_error) json["l2_error"] = number_or_null(*metrics.l2_error);
  if (metrics.hausdorff) json["hausdorff"] = number_or_null(*metrics.hausdorff);
  if (metrics.curve_recall) json["curve_recall"] = *metrics.curve_recall;
  if (metrics.curve_recall_tolerance) json["curve_recall_tolerance"] = *metrics.curve_recall_tolerance;
  if (metrics.vertex_distance) {
    json["vertex_distance_mean"] = metrics.vertex_distance->mean;
    json["vertex_distance_max"] = metrics.vertex_distance->max;
  }
  if (metrics.topology) {
    json["manifold"] = metrics.topology->manifold;
    json["components"] = metrics.topology->components;
    json["closed_components"] = metrics.topology->closed_components;
    json["dangling_vertices"] = metrics.topology->dangling_vertices;
    json["branching_vertices"] = metrics.topology->branching_vertices;
  }
  if (metrics.edges) {
    json["exact"] = metrics.edges->exact;
    json["edge_precision"] = metrics.edges->precision;
    json["edge_recall"] = metrics.edges->recall;
    json["edge_f1"] = metrics.edges->f1;
  } else if (metrics.topology) {
    // A curve on vertices of its own has edges, but none between samples: the comparison
    // with the true adjacency is undefined, not zero.
    for (const char* key : {"exact", "edge_precision", "edge_recall", "edge_f1"}) json[key] = nullptr;
  }
  if (metrics.medial_axis_hausdorff) json["medial_axis_hausdorff"] = number_or_null(*metrics.medial_axis_hausdorff);
  if (metrics.dominant_points) {
    json["dominant_points"] = metrics.dominant_points->count;
    json["compression_ratio"] = number_or_null(metrics.dominant_points->compression_ratio);
    json["integral_square_error"] = number_or_null(metrics.dominant_points->integral_square_error);
    json["figure_of_merit"] = number_or_null(metrics.dominant_points->figure_of_merit);
  }
  return json;
}

}  // namespace curvebench
