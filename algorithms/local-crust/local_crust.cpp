// The "local-crust" algorithm: the one-step crust and its anti-crust skeleton.
#include "core/registry.h"
#include "local-crust/anti_crust_medial_axis.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {
namespace {

class LocalCrust final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "local-crust",
        "Local (one-step) crust and anti-crust: one InCircle test per Delaunay/Voronoi edge pair gives curve and "
        "skeleton (Gold, SCG 1999; Gold, Snoeyink, Algorithmica 2001)",
        kCurve | kMedialAxis, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    const DelaunayVoronoi& dv = *sites.delaunay;
    OneStepCrust crust = one_step_crust(dv);
    timer.lap("crust");
    SiteResult result;
    result.medial_axis = anti_crust_medial_axis(dv, crust);
    result.curve_edges = std::move(crust.curve);
    timer.lap("skeleton");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(LocalCrust);

}  // namespace
}  // namespace curvebench
