// Section 3.4: dominant points (high-curvature samples) from the labeling patterns on
// Voronoi cells.
//
// A sample is dominant if its Voronoi cell, read cyclically, has an IOI or OIO pattern (a
// single vertex c whose label differs from both its neighbours along the cell boundary) that
// passes the paper's filter: both terminal vertices lie strictly across the line through the
// sample orthogonal to (c - sample).
//
// Read locally. Consecutive vertices of the cell of site s are the triangles on the two sides
// of a Delaunay edge at s, so c is the centre of a pattern in the cell of s exactly when the
// label of triangle c changes across both of its edges at s (both are curve edges), and the
// terminals are the triangles across those two edges. One pass over the triangles therefore
// finds every pattern without walking a cell (extract_curve_and_dominant_points).
//
// Gaps filled here. An unbounded cell is read as its chain of finite vertices closed by the
// infinite (outer) vertex. The infinite vertex can be a terminal of a pattern (a convex
// hull sample whose cell has a single inner vertex is the tip of an inner medial-axis branch:
// OIO), with the outward normal of the adjacent hull edge as its direction, but never the
// centre: it stands for the whole unbounded part of the cell, not for one Voronoi vertex, and
// every hull sample with two or more finite vertices would otherwise show IOI.
//
// In:  Delaunay/Voronoi arrays, a triangle `centre` and one of its corners, such that the
//      triangle is the centre of an IOI/OIO pattern in the cell of the site at that corner.
// Out: true if both terminals (the triangles across the centre's two edges at the site, or
//      the infinite vertex across a hull edge) pass the filter.
#pragma once

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

bool passes_dominant_point_filter(const DelaunayVoronoi& dv, int centre, int corner);

}  // namespace curvebench
