// The "fitconnect" algorithm: FitConnect's connectivity (fitted_neighborhoods.h), then, in the
// authors' default mode, the samples blended onto their fitted circles (fitconnect.h), timed
// as two phases.
#include <utility>
#include <vector>

#include "core/registry.h"
#include "fitconnect/fitconnect.h"
#include "fitconnect/fitted_neighborhoods.h"

namespace curvebench {
namespace {

class FitConnectAlgorithm final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "fitconnect",
        "FitConnect: connecting noisy 2D samples by fitted neighbourhoods (Ohrhallinger, Wimmer; CGF 2018)",
        kCurve | kMovedPoints,
        {max_neighbors_parameter(),
         boolean_parameter("blend", true,
                           "move the samples onto their fitted circles (the authors' default mode); false: input positions")},
        SiteInput::kDistinctPoints,
        // A line is an open curve to the authors' code: their fits take the degenerate branch
        // (spec 2.1) and the samples link along it, with the same edges as here.
        CollinearInput::kReconstructed};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    FittedNeighborhoods fits = connect_fitted_neighborhoods(sites.points, params, timer);
    SiteResult result;
    result.moved_points = params.boolean("blend") ? blended_positions(sites.points, fits)
                                                  : std::vector<Point2>(sites.points.begin(), sites.points.end());
    result.curve_edges = std::move(fits.edges);
    timer.lap("blend");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(FitConnectAlgorithm);

}  // namespace
}  // namespace curvebench
