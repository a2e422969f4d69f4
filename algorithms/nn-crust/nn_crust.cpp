#include "nn-crust/nn_crust.h"

#include "core/phase_timer.h"
#include "nn-crust/nn_crust_edges.h"

namespace curvebench {
namespace {

class NnCrust final : public Algorithm {
 public:
  std::string name() const override { return "nn-crust"; }
  std::string description() const override {
    return "NN-crust: each sample's nearest-neighbour edge and shortest half-neighbour edge, among Delaunay "
           "edges (Dey, Kumar; SODA 1999)";
  }
  unsigned outputs() const override { return kCurve; }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const override {
    resolve_parameters(parameters(), params, name());
    PhaseTimer timer;
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());
    std::vector<Edge> edges = nn_crust_edges(dv);
    timer.lap("nn_crust");
    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.curve_edges = to_input_indices(dv, std::move(edges));
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_nn_crust_algorithm() { return std::make_unique<NnCrust>(); }

}  // namespace curvebench
