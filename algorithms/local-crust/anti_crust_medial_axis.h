// The interior part of the one-step anti-crust (skeleton), as a medial axis.
//
// In:  the Delaunay/Voronoi arrays and their one-step crust classification.
// Out: the Voronoi vertices of the triangles inside the crust's even-odd region that lie in
//      that region themselves, with their circumradii, and the anti-crust Voronoi edges
//      joining two of them. Coinciding vertices (co-circular samples, joined by zero-length
//      Voronoi edges) are merged into one vertex, as the labeler does.
//
// The region is the even-odd region that the L2 metric scores (harness/metrics/even_odd_areas.h)
// for the crust edges, read off the triangulation: the faces are the sets of triangles joined
// across non-crust edges, plus the unbounded face; a crust edge with the same face on both
// sides (a dangling edge, a bridge, what is left of a curve with a gap) bounds nothing; a
// face is inside when the least number of the remaining crust edges a path to infinity
// crosses is odd. On closed crusts this is the classical parity fill; on a crust with a gap
// it does not depend on the order of a walk, as parity along a breadth-first walk would.
//
// A triangle in the region need not have its Voronoi vertex there: a flat triangle of three
// samples on a straight stroke has its circumcentre across the shape, far outside it (glyph
// outlines, README.md). Gold's anti-crust is the skeleton of the crust's region, so such a vertex
// is no part of the interior skeleton and is left out (voronoi/circumcenters_in_region.h).
#pragma once

#include "core/reconstruction.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust);

}  // namespace curvebench
