// How many curve edges each sample has under a labeling of the Voronoi vertices.
//
// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer).
// Out: per site, the number of Delaunay edges at it whose two sides differ in label: its
//      edges in the curve labeling/extract_shapes.h reads from the labels. Each edge is
//      counted once, from its inner side, so the pass touches the inner triangles only.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> curve_edges_per_sample(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner);

}  // namespace curvebench
