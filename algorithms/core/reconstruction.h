// What every algorithm returns, each part present only if the algorithm produces it, plus
// timings per phase. Every index into points refers to the caller's input points, in input
// order (duplicates map to their first occurrence).
#pragma once

#include <optional>
#include <span>
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

// A graph on vertices of its own: what a non-interpolating method outputs as its curve.
struct PolylineGraph {
  std::vector<Point2> vertices;
  std::vector<Edge> edges;  // indices into `vertices`
};

struct Reconstruction {
  // Edges between input points: the curve of an interpolating or a denoising method.
  std::optional<std::vector<Edge>> curve_edges;
  // A denoising method's new position of every input point (the curve edges join these).
  std::optional<std::vector<Point2>> moved_points;
  // The curve of a method that places vertices of its own (then curve_edges is absent).
  std::optional<PolylineGraph> new_curve;
  std::optional<MedialAxis> medial_axis;
  std::optional<std::vector<int>> dominant_points;  // input indices, ascending
  std::vector<std::pair<std::string, double>> timing_ms;  // phases in order, then "total"
  int distinct_points = 0;
};

// The reconstructed curve as segments between vertices, whichever kind of method made it.
struct CurveView {
  std::span<const Point2> vertices;  // the input points, their moved positions, or the method's own vertices
  std::span<const Edge> edges;
  bool on_input_points = false;      // edges join input points (by index), so they compare with the true adjacency
};

// The curve of `result` for the input `points`; nullopt when it has none.
inline std::optional<CurveView> curve_view(const Reconstruction& result, std::span<const Point2> points) {
  if (result.curve_edges) {
    return CurveView{result.moved_points ? std::span<const Point2>(*result.moved_points) : points, *result.curve_edges, true};
  }
  if (result.new_curve) return CurveView{result.new_curve->vertices, result.new_curve->edges, false};
  return std::nullopt;
}

}  // namespace curvebench
