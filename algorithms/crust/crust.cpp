// The "crust" algorithm: the Delaunay edges of the sites that survive adding their Voronoi
// vertices (crust_triangulation.h).
#include "core/registry.h"
#include "crust/crust_triangulation.h"

namespace curvebench {
namespace {

class Crust final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "crust",
        "Crust: Delaunay edges of the samples plus their Voronoi vertices that join two samples (Amenta, Bern, "
        "Eppstein; GMIP 1998)",
        kCurve, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = delaunay_edges_with_voronoi_vertices(*sites.delaunay);
    timer.lap("crust");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(Crust);

}  // namespace
}  // namespace curvebench
