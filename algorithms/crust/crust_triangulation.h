// The crust's triangulation (Amenta, Bern, Eppstein 1998): the Delaunay triangulation of
// the sites together with all their Voronoi vertices, of which the crust keeps the edges
// between two sites.
//
// In:  the shared Delaunay/Voronoi layer of the sites (dimension 2).
// Out: the Delaunay edges between two sites in the triangulation of the sites and the
//      layer's Voronoi vertices (circumcentres), as site pairs, each once, in ascending
//      order. A Voronoi vertex equal to a site counts as that site; one whose computed
//      position is not finite (a hull triangle flat to rounding, its centre beyond the range
//      of doubles) is left out: its only effect would be on hull edges.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> delaunay_edges_with_voronoi_vertices(const DelaunayVoronoi& dv);

}  // namespace curvebench
