// Crawl through Neighbors (Parakkat, Muthuganapathy; Computer Graphics Forum 35(5), SGP 2016),
// as specified in specification.md, with the spec's sound choices (section 3).
//
// In:  the Delaunay/Voronoi arrays of distinct sites. Dimension 2 is the method's input;
//      below it (collinear sites, fewer than 3 sites) see the last paragraph.
// Out: edges between sites (make_edge order, sorted, each once), grown greedily on Delaunay
//      edges (spec section 2):
//      1. seeds: the Delaunay edges uv with u the nearest neighbour of v or v of u, shortest
//         first;
//      2. a component starts at the next seed whose two ends are both unused;
//      3. it grows, at the end whose nearest unused Delaunay neighbour is nearer (the second
//         end on a tie), by the edge to that neighbour; after at least 4 growth steps it closes
//         as soon as one end is the other's second-nearest Delaunay neighbour; it stays open
//         when neither end has an unused neighbour. Back to 2 until the seeds run out.
//      Every vertex has degree <= 2; components are paths, or cycles of at least 6 sites;
//      sites never reached stay isolated.
//
// The reference's infinite vertex (a phantom neighbour at the origin for hull sites) is left
// out: only finite Delaunay neighbours count. Distances are Euclidean, in double precision,
// without the reference's 9999 cut-off. Equal distances, where the reference follows CGAL's
// circulation and edge order, go to the smaller site index; the two are the same in general
// position.
//
// Below dimension 2 there is no triangulation; the reference (CGAL's 1-D triangulation) then
// grows one chain along the line, so the result is the path through the sites in
// lexicographic order: one edge for 2 sites, none for 0 or 1.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<Edge> crawl_edges(const DelaunayVoronoi& dv);

}  // namespace curvebench
