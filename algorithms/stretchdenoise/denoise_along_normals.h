// Pass 2 of StretchDenoise (Ohrhallinger & Wimmer, "StretchDenoise: Parametric Curve
// Reconstruction with Guarantees by Separating Connectivity from Residual Uncertainty of
// Samples", Pacific Graphics 2018). Spec: specification.md §2.3-2.9.
//
// In:  the sites, pass 1's result (connect_fitted_neighborhoods on the same sites), and one
//      noise extent sigma_i >= 0 per site (the radius of the disc the true curve point of
//      sample i lies in; given by a sensor model or estimated, see stretch_denoise.h).
// Out: one position per site. Vertices of every linked component move along their oriented
//      fit normals so that, per window of vertices one line fits through (spec 2.8), the
//      angle proxies are minimised in the least-squares sense subject to the samples' signed
//      distances to the polygon balancing, each vertex staying within sigma of its sample
//      (spec 2.9). Chain ends (LEAF points, broken links) stay fixed; samples that are not
//      on a component keep their position. A window grows to at most `max_window` vertices
//      (0: as many as fit, as in the reference; growing one costs its size squared and more).
#pragma once

#include <span>
#include <vector>

#include "core/point.h"
#include "fitconnect/fitted_neighborhoods.h"

namespace curvebench {

std::vector<Point2> denoise_along_normals(std::span<const Point2> sites, const FittedNeighborhoods& fits,
                                          std::span<const double> noise_extents, int max_window = 0);

}  // namespace curvebench
