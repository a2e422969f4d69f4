// The topology of a reconstructed curve, read from its edges alone.
//
// In:  edges between vertex indices (any graph; duplicate edges count once).
// Out: the degree census and components of the graph formed by the vertices that have an
//      edge. The curve is a manifold when there is at least one edge and every such vertex
//      has degree 2, i.e. the edges form disjoint closed curves. A closed component is a
//      connected component in which every vertex has degree 2 (one closed curve); compare
//      `closed_components` with the number of true curves.
#pragma once

#include <span>

#include "core/point.h"

namespace curvebench {

struct CurveTopology {
  bool manifold = false;
  int components = 0;           // connected components with at least one edge
  int closed_components = 0;    // components that are a single closed curve
  int dangling_vertices = 0;    // degree 1: an end of an open chain
  int branching_vertices = 0;   // degree 3 or more
};

CurveTopology curve_topology(std::span<const Edge> edges);

}  // namespace curvebench
