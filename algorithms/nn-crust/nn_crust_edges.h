// The NN-crust of Dey and Kumar, "A simple provable algorithm for curve reconstruction"
// (SODA 1999).
//
// In:  the Delaunay/Voronoi arrays of the samples (dimension 2).
// Out: edges between sites, each once, in no particular order: for every sample p, the edge
//      to its nearest neighbour q, and the edge to its "half neighbour": the nearest s among
//      p's Delaunay neighbours with angle(q - p, s - p) >= 90 degrees, if there is one. For an
//      epsilon-sample of a smooth closed curve with epsilon < 1/3 these are exactly the
//      edges between samples adjacent along the curve.
//
// Both searches run over Delaunay edges only (a nearest neighbour is always a Delaunay
// neighbour, and Dey and Kumar restrict the half neighbour to them). Equal distances go to
// the smaller site index, so that e.g. on a uniformly sampled circle one of the two equally
// near neighbours is the nearest and the other the half neighbour. Distances and the angle
// test are evaluated in double precision (exact for integer coordinates below 2^25).
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> nn_crust_edges(const DelaunayVoronoi& dv);

}  // namespace curvebench
