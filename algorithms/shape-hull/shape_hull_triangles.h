// The Delaunay sculpting of Peethambaran and Muthuganapathy (Computer-Aided Design 58, 2015),
// in the plane: the triangles of the shape-hull graph SHG(S).
//
// In:  the Delaunay/Voronoi arrays of the samples. Below dimension 2 there are no triangles.
// Out: one flag per triangle of dv: 1 if it is in SHG(S), 0 if sculpting removed it.
//
// Sculpting (spec section 2): starting from all Delaunay triangles, a boundary triangle
// (a triangle with an edge on the outside) is removed, in decreasing order of circumradius,
// when
//   a. it has exactly one boundary edge e (two or three: "dangling", kept),
//   b. the vertex opposite e is not yet on the boundary ("junction", kept), and
//   c. its circumcentre lies outside the current shape: the segment from the triangle's
//      centroid to its circumcentre leaves the shape before reaching the circumcentre (a
//      circumcentre on an edge or vertex counts as inside).
// Rules a and b keep the kept triangles a topological disk whose boundary runs through every
// convex hull site. Every triangle is decided once, at the first time it is taken from the
// queue after becoming a boundary triangle, and never comes back.
//
// Ties: equal circumradii go to the smaller triangle index. The test of rule c is exact:
// it decides for the true centroid and circumcentre, not for their rounded values.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<std::uint8_t> shape_hull_triangles(const DelaunayVoronoi& dv);

}  // namespace curvebench
