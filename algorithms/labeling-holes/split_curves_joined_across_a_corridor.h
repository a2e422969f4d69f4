// Step 10 of labeling-holes: corridors of inner triangles that the crust reads as outside,
// relabelled outer where that leaves a 1-manifold (two curves the labels join, split again).
//
// Past the sampling bounds the paper's walk can stop the Voronoi vertices between two curves
// (Definition 5 against a poor tangent estimate, gap 2) and leave a corridor of inner
// triangles inside the hull that joins them into one closed curve through two long edges:
//   - with no sample swallowed, every sample keeping two curve edges (the disjoint family at
//     epsilon 1.0, seed 3: edges 2-23 and 3-22 instead of 2-3 and 22-23). Nothing in the
//     labels' topology shows it, and a narrow neck of one shape (a dumbbell's) looks the same
//     with the roles swapped: its walls are the curve edges, the sides across it face the lobes;
//   - with samples swallowed, whose cells are all inner, where step 8's walk from the mouth
//     stops halfway against a poor tangent estimate (epsilon 1.0, seed 5: the corridor 6-25 /
//     4-27 over samples 5 and 26; the walk from the mouth (5, 25, 6) stops across 5-26).
//
// The two readings are told apart by the local crust test of Gold and Snoeyink
// (local-crust/one_step_crust.h): a Delaunay edge pq is a crust edge when some circle through
// p and q is empty of samples and of the two Voronoi vertices of pq's Voronoi edge. On an
// epsilon-sample (epsilon < 0.252, Amenta, Bern and Eppstein) the crust edges are exactly the
// curve edges: an edge along the curve is crust, an edge across the medial axis is not. A
// corridor is grown from an inner triangle with a curve edge that fails the test, through the
// edges between inner triangles that fail it too (they cross the medial axis between the two
// curves, and the Voronoi edges dual to them are Gold's anti-crust, the skeleton). Its other
// edges towards inner triangles pass the test: they are where the crust puts the curve. The
// corridor is relabelled outer when it has such edges and every sample of it then has exactly
// two curve edges: the labels then agree with the crust around the corridor, and the curve is
// a 1-manifold there. Curve edges on its boundary that pass the test leave the curve with it:
// requiring all of them to fail the test kept wrong labels (the disjoint family at epsilon
// 1.0, seed 4, and glyph outlines at 100-800 points). Where the crust reads the
// paper's labels right, the corridor from a rejected curve edge is a whole interior bounded by
// curve edges, with no edge towards an inner triangle, and nothing changes. The same rule
// opens a one-triangle pocket at a sharp concave corner that the paper closed with a chord
// (the 8-pointed star at epsilon 0.12, seed 1: 325-327 instead of 325-326-327).
//
// The same with the labels swapped (`side` 0): corridors of outer triangles inside the shape
// that the crust reads as inside, relabelled inner. Where a stroke is narrower than the gaps
// between its samples, the paper's walk can enter it through a triangle that spans it
// (holes.json's 7 at 50 random samples, seed 1: the triangle 11-38-39 across the stroke,
// whose edge 38-39 lies on the convex hull; the curve runs 11-38 and 11-39 instead of 38-39,
// and sample 11 has four curve edges). Its edges to inner triangles fail the test. A hull
// edge of such a corridor needs none: outside Conv(P) lies outside every polygon on the
// samples (Section 3.3 of the paper), so with the corridor inside, the curve runs along the
// hull edge; relabelled inner, the curve takes 38-39 and every sample keeps two.
//
// In:  Delaunay/Voronoi arrays (dimension 2); `inner`, per triangle, 1 for inner (the infinite
//      vertex is outer); `seeds`, the triangles to grow corridors from, in order (a seed
//      whose label is not `side`, lies in a corridor grown already, or has no curve edge that
//      fails the test is skipped); `side`, the label of the corridors' triangles.
// Out: `inner` with the corridors' triangles set to 1 - side; returns those triangles.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> split_curves_joined_across_a_corridor(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                       std::span<const int> seeds, std::uint8_t side = 1);

// The same from every triangle: the seeds are the triangles of label `side` at curve edges with
// an angle of 45 degrees or more opposite them on either side (a curve edge that fails the
// test has one), in index order, so that a pass over the triangles' own corners finds them.
std::vector<int> split_curves_joined_across_a_corridor(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner, std::uint8_t side = 1);

}  // namespace curvebench
