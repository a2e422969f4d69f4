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
// Which ear, when the apex has two (its own ear at a tip of its curve, and the bridge): the
// one without s's shortest curve edge. The edge from a sample to its nearest neighbour is an
// edge of the curve (Dey and Kumar's NN-crust, SODA 1999, for epsilon < 1/3), and the ear
// of the curve s lies on holds s's edges to its neighbours along the curve; the bridge spans
// the gap between two curves, longer than the spacing along them. An ear whose apex has two
// curve edges, or that holds the apex's shortest curve edge, keeps its label.
//
// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer), as label_voronoi_vertices_with_holes leaves it.
// Out: `inner` with those ears set to 0, in triangle order, each decided on the labels as
//      they are after the ears before it; returns how many were relabelled.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

int relabel_bridging_ears(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner);

}  // namespace curvebench
