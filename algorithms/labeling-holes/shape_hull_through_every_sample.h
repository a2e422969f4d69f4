// Step 11 of labeling-holes: where the labels end with samples off the curve or on a pinch, or
// with a curve step 8 split in two, the shape-hull of the samples instead, if its curve puts
// more samples on a 1-manifold and brings on at least twice as many as it takes off, or leaves
// at most half as many off (and, where the labels hold several curves, joins them only as
// pieces of one).
//
// Every sample of a curve lies on it between its two neighbours, so labels under which a
// sample has no curve edge, or four, are wrong there. Steps 6-10 repair the faults they can
// explain and leave the others (a sparse outline whose pocket the paper closed at its mouth
// and step 8 cannot open: the star at 30 random samples, seed 2, has 6 and 7 swapped and 8
// off the curve, 15 and 16 swapped and 12-14 off it). Shape-hull (Peethambaran and
// Muthuganapathy, Computer-Aided Design 2015, by the paper's first author; `shape-hull/`)
// sculpts the Delaunay triangulation from the convex hull, one triangle at a time, by
// decreasing circumradius, while the triangle's circumcentre lies outside the shape, and
// never through a sample already on the boundary. Its triangles are a topological disk,
// so its curve is one closed curve; on that star it is the true one.
//
// It is taken only where it can be the answer and the labels cannot (the caller,
// label_voronoi_vertices_with_holes.cpp, decides where): the labels are wrong somewhere (a
// sample has other than two curve edges, or step 8 opened a pocket that left its samples on
// two curves), no missed curve was taken at step 4 (shape-hull's one curve cannot represent
// holes, nested or disjoint curves, nor the small closed curves noise leaves: this also spares
// noisy input the sculpting's cost), and shape-hull's curve explains more of the samples
// (take_the_shape_hull_where_it_puts_more_samples_on_the_curve). Where the labels' only faults
// are pinches, their curve is a tour through every sample, and the caller compares the two
// tours' lengths instead (shape_hull_where_it_is_shorter.h). Where the labels hold several
// curves, shape-hull's must explain most of what they cannot and join them only as pieces of
// one curve (take_the_shape_hull_where_it_joins_pieces_of_one_curve). Shape-hull's kept
// triangles then become the inner vertices, so the medial axis and the dominant points follow
// its curve as they follow the labels'.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer); `curve_edges`, its counts per sample (curve_edges_per_sample.h).
// Out: whether the curve edges join every sample that has one into one connected curve.
bool curve_edges_form_one_connected_curve(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                          const std::vector<int>& curve_edges);

// In:  Delaunay/Voronoi arrays; `inner`, the labels to replace.
// Out: true with `inner` set to shape-hull's triangles if under them every sample has exactly
//      two curve edges, else false with `inner` as it came.
bool take_the_shape_hull_through_every_sample(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner);

// In:  Delaunay/Voronoi arrays; `inner`, the labels to replace, whose curve edges form one
//      connected curve (or, after step 8 split it, did before); `curve_edges`, their counts
//      per sample (curve_edges_per_sample.h).
// Out: true with `inner` set to shape-hull's triangles if its curve puts more samples on a
//      1-manifold than the labels' and brings on at least twice as many as it takes off, or
//      leaves at most half as many off, else false with `inner` as it came:
//      - fewer samples have other than two curve edges under shape-hull's triangles than under
//        the labels (with none under the labels, shape-hull's curve passes through every
//        sample);
//      - of the samples on which the two differ, at least twice as many are on shape-hull's
//        1-manifold and off the labels' as the other way round (a curve that explains the
//        walls of a pocket the paper closed off at its mouth, or a wing the labels cut across,
//        outweighs a concave corner or two the sculpting stops short of), or shape-hull leaves
//        at most half as many samples off as the labels. Nearer than two to one the counts say
//        little (outlines with outliers, where hundreds of samples are off both curves);
//      - where a sample is left off both, no sample that shape-hull brings onto the curve alone
//        (from off the labels' curve, with neither curve neighbour brought on from off it too)
//        is a spike over a curve edge of the labels: between the two ends of such an edge, and
//        farther from each than they lie from each other. That is what an outlier beside the
//        curve looks like, and shape-hull's spike to it would replace a curve edge the labels
//        have right; a sample of the curve the labels skipped lies nearer one of its neighbours.
bool take_the_shape_hull_where_it_puts_more_samples_on_the_curve(const DelaunayVoronoi& dv,
                                                                  std::vector<std::uint8_t>& inner,
                                                                  const std::vector<int>& curve_edges);

// In:  as above, labels whose curve edges form several connected curves (or none).
// Out: true with `inner` set to shape-hull's triangles where its one curve joins them as
//      pieces of one curve, else false with `inner` as it came:
//      - it leaves at most half as many samples off a 1-manifold as the labels, whether or not
//        it takes any off, and brings on no lone sample that is a spike (as above);
//      - every edge of its curve that joins two of the labels' curves is no longer than the
//        longest curve edge of the labels at one of its ends. Noise and strokes narrower than
//        the sampling break one curve into pinched pieces that lie as close together as the
//        samples along them (`default.json`'s rose at epsilon 0.13, Gaussian noise 0.1 lfs,
//        seed 3: eight pieces, 21 samples off them, 6 off shape-hull's curve); curves sampled
//        densely enough to be told apart lie farther apart than their samples, and shape-hull,
//        whose triangles stay one disk, would bridge them with longer edges.
bool take_the_shape_hull_where_it_joins_pieces_of_one_curve(const DelaunayVoronoi& dv,
                                                             std::vector<std::uint8_t>& inner,
                                                             const std::vector<int>& curve_edges);

}  // namespace curvebench
