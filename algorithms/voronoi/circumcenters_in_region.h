// Which Voronoi vertices of a region's triangles lie in that region.
//
// In:  the Delaunay/Voronoi arrays and a region given as a set of Delaunay triangles
//      (`in_region[t]` nonzero), e.g. the even-odd region of a curve made of Delaunay edges.
// Out: per triangle, 1 if it is in the region and its Voronoi vertex (circumcentre) lies in
//      the closed union of the region's triangles, else 0.
//
// A triangle inside a curve can have its circumcentre far outside it: three nearly
// collinear samples on a straight stroke make a flat triangle whose circumcentre lies across
// the shape, far outside it. A medial axis must not keep such a vertex.
//
// The circumcentre is located by a remembering stochastic visibility walk from its own
// triangle (Devillers, Pion, Teillaud, "Walking in a triangulation", IJFCS 13(2), 2002):
// cross an edge whose line separates the current triangle from the point, trying the edges
// from a random one, never straight back; it ends with probability 1 in any triangulation,
// and always in a Delaunay one (Edelsbrunner 1990). Orientations are exact (CGAL's
// Exact_predicates_inexact_constructions_kernel), so a centre on an edge is found on it,
// and it counts as in the region if either triangle on that edge is (a circumcentre is
// never a site: its disk is empty). A walk that would leave the convex hull ends outside.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<std::uint8_t> circumcenters_in_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> in_region);

}  // namespace curvebench
