// The priority order of the labeling walks (Algorithm 2 of Peethambaran et al.) and of
// shape-hull's sculpting: Voronoi vertices by decreasing circumradius.
//
// In:  the layer and a list of its finite triangles.
// Out: the list reordered by decreasing circumradius; equal radii keep their order in the
//      list (stable), so a list in index order breaks ties by the smaller index. A
//      least-significant-digit radix sort on the radii's bits: non-negative doubles order
//      like their bit patterns, complemented the largest comes first. Linear in the list's
//      length, and it reads the radii in list order, not at random as a comparison sort
//      through the indices would.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

void sort_by_decreasing_circumradius(const DelaunayVoronoi& dv, std::vector<int>& triangles);

}  // namespace curvebench
