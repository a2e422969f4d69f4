// The interior part of the one-step anti-crust (skeleton), as a medial axis.
//
// In:  the Delaunay/Voronoi arrays and their one-step crust classification.
// Out: the Voronoi vertices inside the crust with their circumradii, and the anti-crust
//      Voronoi edges joining two of them. Coinciding vertices (co-circular samples, joined
//      by zero-length Voronoi edges) are merged into one vertex, as the labeler does.
//
// Inside is decided by parity: a walk over Delaunay triangles from the unbounded face flips
// inside/outside each time it crosses a crust edge (the even-odd fill of the crust). This is
// independent of the walk whenever every sample has even crust degree, as on any union of
// closed curves; otherwise the breadth-first walk from the hull decides.
#pragma once

#include "core/reconstruction.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust);

}  // namespace curvebench
