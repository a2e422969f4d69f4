// FitConnect: S. Ohrhallinger and M. Wimmer, "FitConnect: Connecting Noisy 2D Samples by
// Fitted Neighborhoods", Computer Graphics Forum 2018; implemented from specification.md,
// which follows the authors' code (stefango74/fitconnect). The connectivity and the state
// behind it: fitted_neighborhoods.h.
#pragma once

#include <span>
#include <vector>

#include "core/denoised_curve.h"
#include "core/point.h"
#include "fitconnect/fitted_neighborhoods.h"

namespace curvebench {

// The authors' default *blend* mode (spec 2.8).
// In:  the sites and connect_fitted_neighborhoods(sites, ...) of the same sites.
// Out: one position per site: a sample that is SHARP or linked to a SHARP sample keeps its
//      position; every other one moves to the average of its projection onto its own circle
//      (if MANIFOLD) and the hits of its normal line on the circles of the MANIFOLD samples
//      whose sides hold it, each inside that sample's arc and on its side of it; a sample
//      with no such contribution keeps its position. A MANIFOLD sample whose fit is a line
//      (the fit's degenerate branch, or its neighbourhood collinear up to rounding) has no
//      circle: it contributes its own position and moves no neighbour (README.md).
std::vector<Point2> blended_positions(std::span<const Point2> sites, const FittedNeighborhoods& fits);

// In:  distinct finite sites; `blend`: the authors' default mode (true) or mode *none*;
//      `max_neighbors`: the growth cap of connect_fitted_neighborhoods (0 = unbounded).
// Out: the edges of connect_fitted_neighborhoods over the site indices, and one position per
//      site: blended_positions with `blend`, else the input positions. Fewer than three
//      sites: no edges, unmoved positions.
DenoisedCurve fitconnect(std::span<const Point2> sites, bool blend = true, int max_neighbors = kDefaultMaxNeighbors);

}  // namespace curvebench
