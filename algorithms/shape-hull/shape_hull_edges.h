// The shape-hull SH(S) of Peethambaran and Muthuganapathy (Computer-Aided Design 58, 2015):
// the boundary of the shape-hull graph, a reconstruction of one closed curve without
// parameters.
//
// In:  the Delaunay/Voronoi arrays of the samples (no edges below dimension 2).
// Out: the edges between sites that bound the triangles kept by shape_hull_triangles (an
//      edge of a kept triangle whose other side is removed or unbounded), each once, sorted.
//      They form one simple closed polygon through every convex hull site; sites inside the
//      shape get no edges.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> shape_hull_edges(const DelaunayVoronoi& dv);

}  // namespace curvebench
