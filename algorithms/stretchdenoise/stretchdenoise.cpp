// The "stretchdenoise" algorithm: FitConnect's connectivity, then the samples moved along
// their normals within their noise extents (stretch_denoise.h), timed as two phases.
#include <limits>

#include "core/registry.h"
#include "stretchdenoise/denoise_along_normals.h"
#include "fitconnect/fitted_neighborhoods.h"
#include "stretchdenoise/stretch_denoise.h"

namespace curvebench {
namespace {

class StretchDenoise final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "stretchdenoise",
        "StretchDenoise: connectivity from fitted neighbourhoods, then samples moved within their noise extents by "
        "bounded least squares (Ohrhallinger, Wimmer; Pacific Graphics 2018)",
        kCurve | kMovedPoints,
        {real_parameter("noise_extent", 0.0, 0.0, std::numeric_limits<double>::max(),
                        "noise extent (input units) of every sample; 0: each sample's estimate from its circle fit"),
         real_parameter("min_noise_extent", 0.0, 0.0, std::numeric_limits<double>::max(),
                        "floor on every sample's noise extent (input units; 0: none)"),
         max_neighbors_parameter(),
         integer_parameter("max_window", 256, 0, 1000000000,
                           "vertices one least-squares window may grow to (0: unbounded, as the authors' code, whose "
                           "cost grows with the fourth power of a window on a straight run)")},
        SiteInput::kDistinctPoints,
        // Pass 1 is FitConnect's, which links collinear samples along the line (fitconnect_algorithm.cpp).
        CollinearInput::kReconstructed};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    FittedNeighborhoods fits = connect_fitted_neighborhoods(sites.points, params, timer);
    SiteResult result;
    result.moved_points = denoise_along_normals(
        sites.points, fits, noise_extents(fits, params.real("noise_extent"), params.real("min_noise_extent")),
        static_cast<int>(params.integer("max_window")));
    result.curve_edges = std::move(fits.edges);
    timer.lap("denoise");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(StretchDenoise);

}  // namespace
}  // namespace curvebench
