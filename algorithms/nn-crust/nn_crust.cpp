// The "nn-crust" algorithm: NN-crust on the shared Delaunay layer (nn_crust_edges.h).
#include "core/registry.h"
#include "nn-crust/nn_crust_edges.h"

namespace curvebench {
namespace {

class NnCrust final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "nn-crust",
        "NN-crust: each sample's nearest-neighbour edge and shortest half-neighbour edge, among Delaunay edges (Dey, "
        "Kumar; SODA 1999)",
        kCurve, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = nn_crust_edges(*sites.delaunay);
    timer.lap("nn-crust");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(NnCrust);

}  // namespace
}  // namespace curvebench
