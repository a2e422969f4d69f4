// The "optimal-transport" algorithm behind the common interface: CGAL's
// Optimal_transportation_reconstruction_2 (de Goes, Cohen-Steiner, Alliez, Desbrun, "An
// optimal transport approach to robust reconstruction and simplification of 2D shapes",
// SGP 2011). It starts from the Delaunay triangulation of the samples and collapses edges in
// order of increasing optimal-transport cost, then keeps the edges that receive mass.
//
// In:  points; parameters `tolerance`, `vertices`, `relocation`, `flip` (see parameters()).
//      The defaults stop at a Wasserstein cost of 2 mean nearest-neighbour spacings (a
//      closed polygon on the epsilon-samples of the tests, where 1 leaves gaps) and turn
//      off CGAL's relocation and edge flips, which cost time and change little on clean
//      samples. CGAL's exhaustive priority queue is kept: its random-sample alternative is
//      no faster here and depends on CGAL's time-seeded default random generator.
// Out: the curve as new vertices and edges between them. The method does not interpolate:
//      its vertices are a subset of the samples, moved when relocation is on. So
//      Reconstruction::curve_vertices holds the output vertices (sorted by x, then y) and
//      curve_edges index into them, not into the input; a vertex that received mass but no
//      edge is listed without an edge. The JSON writes them as "curve": {"vertices": [[x, y],
//      ...], "edges": [[i, j], ...]}.
//
// CGAL's headers are included only by optimal_transport.cpp.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_optimal_transport_algorithm();

}  // namespace curvebench
