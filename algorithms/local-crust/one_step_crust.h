// The one-step crust and anti-crust of Gold, "Crust and anti-crust: a one-step boundary and
// skeleton extraction algorithm" (SCG 1999; with Snoeyink, Algorithmica 30, 2001).
//
// In:  the Delaunay/Voronoi arrays of the samples (dimension 2).
// Out: for every Delaunay edge pq, exactly one of: pq is a crust edge (curve), or its dual
//      Voronoi edge vw is an anti-crust edge (skeleton). The test looks only at pq and vw:
//      pq is crust if some circle through p and q is empty of samples and of both Voronoi
//      vertices v and w (the local form of the crust condition of Amenta, Bern, Eppstein).
//      When pq crosses vw this is Gold's InCircle test on the quadrilateral p, v, q, w (w
//      outside the circle through p, q, v); unlike that test it does not depend on which
//      Voronoi vertex is called v when the quadrilateral is not convex.
//
// With r and s the third corners of the two triangles on pq, the circles through p and q
// empty of samples are centred on vw, and one of them misses v and w exactly when
//   angle(p r q) + angle(p s q) < 90 degrees,
// i.e. when cos of that sum is positive. A hull edge has no s: it is crust when the angle
// at r is acute. Both are evaluated exactly (double precision with an error bound, exact
// rationals when the sign is in doubt), so co-circular samples (angle sum 180 degrees:
// never crust) and right angles (sum 90 degrees: not crust) are decided consistently.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

struct OneStepCrust {
  // Per triangle and corner k: 1 if the Delaunay edge opposite corner k is a crust edge, 0 if
  // its dual Voronoi edge is an anti-crust edge. Equal on both triangles of an edge.
  std::vector<std::array<std::uint8_t, 3>> is_crust;
  std::vector<Edge> curve;  // the crust edges between sites, each once, in triangle order
};

OneStepCrust one_step_crust(const DelaunayVoronoi& dv);

// The test above for one edge: whether the Delaunay edge opposite corner k of triangle t is a
// crust edge.
bool is_one_step_crust_edge(const DelaunayVoronoi& dv, int t, int k);

}  // namespace curvebench
