// What every algorithm returns: the reconstructed curve, the interior medial axis and the
// dominant points, each present only if the algorithm produces it, plus timings per phase.
// Indices refer to the caller's input points (duplicates map to their first occurrence),
// except where `curve_vertices` is set (non-interpolating methods): then curve edges index
// into `curve_vertices`.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct MedialAxis {
  std::vector<Point2> vertices;
  std::vector<double> radii;  // radius of the empty disk centred at each vertex
  std::vector<Edge> edges;    // indices into `vertices`
};

struct Reconstruction {
  std::optional<std::vector<Edge>> curve_edges;
  std::optional<std::vector<Point2>> curve_vertices;  // set only by non-interpolating methods
  std::optional<MedialAxis> medial_axis;
  std::optional<std::vector<int>> dominant_points;
  std::vector<std::pair<std::string, double>> timing_ms;  // phases in order, then "total"
  int distinct_points = 0;
};

}  // namespace curvebench
