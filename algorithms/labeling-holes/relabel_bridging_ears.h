// Bridges between curves: inner ears at a sample with four or more curve edges, relabelled
// outer.
//
// On an epsilon-sample the curve is a 1-manifold through the samples: every sample has
// exactly two curve edges (the two between it and its neighbours along the curve). Past the
// sampling bounds the paper's walk can stop a Voronoi vertex lying between two curves
// (Definition 5 against a poor tangent estimate, gap 2 of labeling/README.md), and the vertex
// then ends inner as an *ear*: an inner vertex with one inner neighbour, attached to one
// curve's interior across an edge a-b and reaching a sample s of another curve, its apex
// (the disjoint family at epsilon 0.7, seed 3: the triangle (3, 40, 41)). Its two edges s-a and
// s-b are then curve edges besides s's own, s has four, and the true edge a-b is missing.
// Relabelling the ear outer takes s-a and s-b out and puts a-b back: s loses two curve edges
// and every other sample keeps its count. It is the smallest change of labels that brings s
// back towards two edges.
//
// Which ear: one whose two edges at s are longer than every other curve edge at s. A bridge
// crosses the medial axis between two curves, so an edge from s to a sample a of another
// curve is at least lfs(s) + lfs(a) long, while s's edges to its neighbours along its curve
// are at most 2 epsilon / (1 - epsilon) lfs(s) (Definition 4), shorter for epsilon <= 1/3:
// the edges to keep are the apex's two shortest, as in Dey and Kumar's NN-crust (SODA 1999),
// whose nearest-neighbour edge is a curve edge. An ear with an edge no longer than another
// curve edge at s (its own curve's ear at a tip, or a stroke pinched at s) keeps its label,
// and so does one whose apex is a corner of an isolated inner vertex: s would be left on a
// closed curve of three samples (a sliver at a corner of a sparse outline), not its curve.
//
// Only where the bridges are all that is wrong: the ears are relabelled when, with them
// outer, every sample has exactly two curve edges, and not at all otherwise. Where samples
// are left with none or four (a sparse outline whose thin strokes the paper closes off, noise),
// an ear at a sample with four edges may be the true interior of a stroke, and the paper's
// labels are kept.
//
// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer), as label_voronoi_vertices_with_holes leaves it; `curve_edges`, its counts per
//      sample (curve_edges_per_sample.h), which the caller passes on to the next step.
// Out: `inner` with those ears set to 0, all decided on the labels as they come in; returns
//      how many were relabelled (0 when the labels are manifold already, or stay non-manifold).
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

int relabel_bridging_ears(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                          const std::vector<int>& curve_edges);

}  // namespace curvebench
