// Section 3.4: dominant points (high-curvature samples) from the labeling patterns on
// Voronoi cells.
//
// In:  Delaunay/Voronoi arrays, the final vertex labels and the curve edges they give
//      (extract_curve_edges, site indices).
// Out: the sites whose Voronoi cell, read cyclically, has an IOI or OIO pattern (a single
//      vertex whose label differs from both its neighbours along the cell boundary) that
//      passes the paper's filter: with c the central vertex, both terminal vertices lie
//      strictly across the line through the sample orthogonal to (c - sample).
//
// Gaps filled here. An unbounded cell is read as its chain of finite vertices closed by the
// infinite (outer) vertex. The infinite vertex can be a terminal of a pattern (a convex
// hull sample whose cell has a single inner vertex is the tip of an inner medial-axis branch:
// OIO), with the outward normal of the adjacent hull edge as its direction, but never the
// centre: it stands for the whole unbounded part of the cell, not for one Voronoi vertex, and
// every hull sample with two or more finite vertices would otherwise show IOI.
#pragma once

#include <span>
#include <vector>

#include "labeling/label_voronoi_vertices.h"

namespace curvebench {

std::vector<int> detect_dominant_points(const DelaunayVoronoi& dv, const VoronoiLabels& labels,
                                        std::span<const Edge> curve_edges);

}  // namespace curvebench
