// Peeling the Longest: A. D. Parakkat, S. Methirumangalath, R. Muthuganapathy, "Peeling the
// longest: A simple generalized curve reconstruction algorithm", Computers & Graphics 74
// (2018), Proc. SMI 2018; spec specification.md, section 2.
//
// In:  the Delaunay/Voronoi arrays of the samples (below dimension 2 there is no triangle and
//      the result is empty); `len` >= 0, the reconnection factor (0: no reconnection);
//      `reference_cb`: the authors' asymmetric degree test instead of the symmetric one.
// Out: edges between sites, make_edge order, sorted, each once:
//   A. peel: S = the Delaunay edges that are never a longest side of an incident triangle
//      ("longest" non-strict: with ties every tied side is longest);
//   B. degree filter: drop (a, b), of length L, if a has two other S-edges shorter than L, or
//      b has (the symmetric rule of spec section 3). With reference_cb, b's count runs over
//      the other S-neighbours of a and of b, distances from b, as the authors' code does.
//      Without ties every site keeps at most two edges;
//   C. only when len > 0: every site left with a single edge (a, b) gets one more, to its
//      nearest Delaunay neighbour x closer than len * d(a, b) whose edge is not yet taken;
//      added edges are scanned in turn, so a chain can run on through isolated sites.
// Lengths are compared as squared double-precision lengths (the authors round to float32).
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> peel_edges(const DelaunayVoronoi& dv, double len = 0.0, bool reference_cb = false);

}  // namespace curvebench
