// StretchDenoise: S. Ohrhallinger, M. Wimmer, "StretchDenoise: Parametric Curve Reconstruction
// with Guarantees by Separating Connectivity from Residual Uncertainty of Samples", Pacific
// Graphics 2018 (arXiv:1808.07778). Spec: specification.md.
//
// In:  distinct sites; the noise extent sigma (radius of the disc around each sample that
//      holds its true curve point): `given_noise_extent` for every sample if > 0, else each
//      sample's estimate from pass 1 (the largest radial residual of its last circle fit,
//      spec 2.4); `min_noise_extent` floors either (0 = off, as in the reference).
//      `max_neighbors` is pass 1's growth cap (fitconnect/fitted_neighborhoods.h; 0 = unbounded).
// Out: edges = FitConnect's connectivity over the site indices (pass 1,
//      connect_fitted_neighborhoods); positions = the sites moved along their normals by
//      pass 2 (denoise_along_normals.h). Fewer than three sites: no edges, positions unchanged.
#pragma once

#include <span>
#include <vector>

#include "core/denoised_curve.h"
#include "core/point.h"
#include "fitconnect/fitted_neighborhoods.h"

namespace curvebench {

// Each sample's noise extent for pass 2 (spec 2.4): `given_noise_extent` if > 0, else the
// sample's pass-1 estimate, floored by `min_noise_extent`.
std::vector<double> noise_extents(const FittedNeighborhoods& fits, double given_noise_extent, double min_noise_extent);

DenoisedCurve stretch_denoise(std::span<const Point2> sites, double given_noise_extent = 0.0,
                              double min_noise_extent = 0.0, int max_neighbors = kDefaultMaxNeighbors);

}  // namespace curvebench
