#include "crust/crust.h"

#include "core/phase_timer.h"
#include "voronoi/delaunay_voronoi.h"

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
    DelaunayVoronoi sites;
    std::vector<Edge> edges = delaunay_edges_with_voronoi_vertices(points, sites, timer);
    require_triangulation(sites, name());
    timer.lap(name());
    Reconstruction result;
    result.distinct_points = sites.site_count();
    result.curve_edges = to_input_indices(sites, std::move(edges));
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_crust_algorithm() { return std::make_unique<Crust>(); }

}  // namespace curvebench
