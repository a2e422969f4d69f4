// Corridors between curves through the space outside the samples' convex hull: inner Voronoi
// vertices outside Conv(P), relabelled outer where that leaves every sample two curve edges.
//
// A Voronoi vertex outside Conv(P) lies outside every polygon on the samples, which is why the
// paper's EVVs outside the hull start the walks (Section 3.3, Lemma 5.1) and why
// label_voronoi_vertices never lets a tangent estimate make one of those inner. A vertex
// outside the hull that is no EVV gets no such protection: past the sampling bounds a walk can
// stop it (Definition 5 against a poor tangent estimate, gap 2 of labeling/README.md). Two such
// vertices then form a corridor that joins two curves into one closed curve through two long
// edges, and every sample still has two curve edges (the disjoint family at epsilon 0.9, seed
// 1: edges 21-25 and 22-24 instead of 21-22 and 24-25). Relabelling them outer splits the
// corridor and gives back the two curves.
//
// Only on a 1-manifold, as on an epsilon-sample: when every sample has exactly two curve edges,
// every inner vertex outside Conv(P) is relabelled outer if every sample then still has
// exactly two, and none otherwise. On a sparse outline the paper's inner triangles can have
// circumcentres outside the hull (a sliver along a flat stroke), and taking them out there
// leaves samples with no edge or four, so the labels stay. Labels with a sample of another
// count (noise, a sparse outline) are left as they are after one pass over the inner
// triangles.
//
// In:  Delaunay/Voronoi arrays (dimension 2); `inner`, per triangle, 1 for inner (the infinite
//      vertex is outer), as the labels are after relabel_bridging_ears; `curve_edges`, their
//      counts per sample (curve_edges_per_sample.h).
// Out: `inner` with those vertices set to 0, or as it came; returns how many were relabelled.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

int relabel_inner_vertices_outside_the_hull(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                            const std::vector<int>& curve_edges);

}  // namespace curvebench
