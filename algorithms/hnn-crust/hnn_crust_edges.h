// The HNN-crust ("half-neighbour" NN-crust) of Ohrhallinger, Mitchell and Wimmer, "Curve
// Reconstruction with Many Fewer Samples" (Computer Graphics Forum 35(5), SGP 2016), as the
// authors' reference code computes it (spec: specification.md).
//
// In:  distinct sites (any order) and k_max, the size of each site's neighbourhood counted
//      with the site itself (the reference hard-codes 15).
// Out: the edges {i, j} over site indices, i < j, sorted, each once, such that i and j choose
//      each other. Site p chooses (spec steps 1-3), among its min(k_max, n) - 1 nearest other
//      sites ranked by (distance, index):
//        a(p), the nearest one, and
//        b(p), the first q after a(p) in rank with |a(p) - q| > |p - q| (strictly on p's side
//              of the perpendicular bisector of p a(p)), or none if no ranked site qualifies.
//      Every site then has degree 0, 1 or 2. The paper's claim is that on an epsilon-sample
//      of smooth closed curves with epsilon < 0.47 these are the edges between samples
//      adjacent along the curves; the cap k_max is what keeps the two ends of a sampled open
//      arc from joining (spec section 3).
//      n <= 1 gives no edges, n = 2 the single edge {0, 1}.
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

std::vector<Edge> hnn_crust_edges(std::span<const Point2> sites, int k_max = 15);

}  // namespace curvebench
