// The crust of Amenta, Bern and Eppstein, "The crust and the beta-skeleton: combinatorial
// curve reconstruction" (Graphical Models and Image Processing 60, 1998), Section 3.
//
// In:  the Delaunay/Voronoi arrays of the samples (dimension 2).
// Out: the crust as edges between sites, in no particular order: the Delaunay edges of the samples together
//      with their Voronoi vertices whose two ends are samples. For an epsilon-sample of a
//      smooth closed curve with epsilon < 0.252 these are exactly the edges between samples
//      adjacent along the curve.
//
// The union is triangulated by the shared layer (delaunay_edges_between_samples, which builds
// no flat arrays: only the sample-sample edges are needed), so a Voronoi vertex equal to a
// sample counts as that sample. A Voronoi vertex whose
// computed position is not finite (a hull triangle flat to rounding) is left out: it lies
// so far away that its only effect would be on hull edges of the samples.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> crust_edges(const DelaunayVoronoi& dv);

}  // namespace curvebench
