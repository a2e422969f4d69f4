#include "stretchdenoise/stretch_denoise.h"

#include <algorithm>
#include <vector>

#include "stretchdenoise/denoise_along_normals.h"
#include "fitconnect/fitted_neighborhoods.h"

namespace curvebench {

std::vector<double> noise_extents(const FittedNeighborhoods& fits, double given_noise_extent, double min_noise_extent) {
  // Spec 2.4: given extents replace the estimate; the optional floor applies to both.
  std::vector<double> sigma(fits.residuals.size());
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    sigma[i] = std::max(given_noise_extent > 0 ? given_noise_extent : fits.residuals[i], min_noise_extent);
  }
  return sigma;
}

DenoisedCurve stretch_denoise(std::span<const Point2> sites, double given_noise_extent, double min_noise_extent,
                              int max_neighbors) {
  FittedNeighborhoods fits = connect_fitted_neighborhoods(sites, max_neighbors);
  DenoisedCurve result;
  result.positions = denoise_along_normals(sites, fits, noise_extents(fits, given_noise_extent, min_noise_extent));
  result.edges = std::move(fits.edges);
  return result;
}

}  // namespace curvebench
