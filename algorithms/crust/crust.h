// The crust of Amenta, Bern and Eppstein, "The crust and the beta-skeleton: combinatorial
// curve reconstruction" (Graphical Models and Image Processing 60, 1998), Section 3, behind
// the common interface. The curve only; no parameters.
//
// In:  samples of a closed curve (at least 3 distinct points, not all collinear).
// Out: the crust: the Delaunay edges of the samples together with their Voronoi vertices
//      whose two ends are samples (voronoi/delaunay_voronoi.h,
//      delaunay_edges_with_voronoi_vertices). For an epsilon-sample of a smooth closed curve
//      with epsilon < 0.252 these are exactly the edges between samples adjacent along the curve.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_crust_algorithm();

}  // namespace curvebench
