#include "crust/crust.h"

#include "core/phase_timer.h"
#include "crust/crust_edges.h"

namespace curvebench {
namespace {

class Crust final : public Algorithm {
 public:
  std::string name() const override { return "crust"; }
  std::string description() const override {
    return "Crust: Delaunay edges of the samples plus their Voronoi vertices that join two samples "
           "(Amenta, Bern, Eppstein; GMIP 1998)";
  }
  unsigned outputs() const override { return kCurve; }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const override {
    resolve_parameters(parameters(), params, name());
    PhaseTimer timer;
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());
    std::vector<Edge> edges = crust_edges(dv);
    timer.lap("crust");
    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.curve_edges = to_input_indices(dv, std::move(edges));
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_crust_algorithm() { return std::make_unique<Crust>(); }

}  // namespace curvebench
