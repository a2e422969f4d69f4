// An algorithm whose whole output is a curve computed from the Delaunay/Voronoi arrays of the
// input (NN-crust): it supplies its name, description and edge function; this class
// builds the triangulation, refuses input without a closed curve, times the two phases
// ("delaunay", then the algorithm's own) and maps sites back to input indices.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/algorithm.h"
#include "core/phase_timer.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

class DelaunayCurveAlgorithm : public Algorithm {
 public:
  using EdgeFunction = std::vector<Edge> (*)(const DelaunayVoronoi&);

  DelaunayCurveAlgorithm(std::string name, std::string description, EdgeFunction curve_edges)
      : name_(std::move(name)), description_(std::move(description)), curve_edges_(curve_edges) {}

  std::string name() const override { return name_; }
  std::string description() const override { return description_; }
  unsigned outputs() const override { return kCurve; }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const override {
    resolve_parameters(parameters(), params, name_);
    PhaseTimer timer;
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name_);
    std::vector<Edge> edges = curve_edges_(dv);
    timer.lap(name_);
    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.curve_edges = to_input_indices(dv, std::move(edges));
    result.timing_ms = timer.finish();
    return result;
  }

 private:
  std::string name_;
  std::string description_;
  EdgeFunction curve_edges_;
};

}  // namespace curvebench
