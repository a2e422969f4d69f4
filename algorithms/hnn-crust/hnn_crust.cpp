// The "hnn-crust" algorithm: HNN-crust on the distinct sites' nearest neighbours (hnn_crust_edges.h).
#include "core/registry.h"
#include "hnn-crust/hnn_crust_edges.h"

namespace curvebench {
namespace {

class HnnCrust final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "hnn-crust",
        "HNN-crust: mutual nearest- and half-neighbour edges among the k_max nearest samples (Ohrhallinger, Mitchell, "
        "Wimmer; CGF 2016, SGP)",
        kCurve,
        {integer_parameter("k_max", 15, 2, 1000,
                           "neighbourhood size counting the sample itself: the half-neighbour is sought among its "
                           "k_max - 1 nearest samples (the cap keeps an open arc's endpoints apart)")},
        SiteInput::kDistinctPoints,
        // The authors' code joins collinear samples into the path along the line, and so do
        // the mutual nearest and half-neighbour rules here.
        CollinearInput::kReconstructed};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = hnn_crust_edges(sites.points, static_cast<int>(params.integer("k_max")));
    timer.lap("hnn-crust");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(HnnCrust);

}  // namespace
}  // namespace curvebench
