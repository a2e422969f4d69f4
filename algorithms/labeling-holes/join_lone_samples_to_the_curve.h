// Step 9 of labeling-holes: samples the curve passes by, joined to it through one triangle.
//
// Every sample of an epsilon-sample lies on the curve, between its two neighbours along it. At
// an undersampled sharp tip the paper's labels can cut the tip off (a star at 30 random
// samples, seeds 1 and 3: the chord 10-12 instead of 10-11-12): the tip's triangle a-s-b has
// its circumcentre outside the hull, beyond the tip, so it is an EVV that starts a walk and
// ends outer (Section 3.3), although the triangle lies inside the curve. The labels' model,
// a triangle inside the curve exactly when its circumcentre is, fails there. The sample s is
// then *lone*: all the triangles around it have one label, so it has no curve edge, while its
// neighbours a and b are joined by the curve edge a-b. Relabelling the triangle a-s-b puts s-a
// and s-b on the curve and takes a-b off it; a and b keep their counts, s gets two. (The same
// holds with the labels swapped: a one-triangle pocket closed at its mouth.)
//
// Which triangle: one of s's triangles whose edge opposite s is a curve edge and which holds
// s's nearest neighbour (on an epsilon-sample the edge to the nearest neighbour is a curve
// edge, as in Dey and Kumar's NN-crust, SODA 1999; an outlier whose nearest sample is no end
// of such an edge stays out); of several, the one through which the curve detours least
// (|sa| + |sb| - |ab|), ties by the smaller triangle index. Lone samples are taken in index
// order, again until none is left or a round joins none: a tip with two lone samples is
// joined one triangle at a time, the second through an edge the first put on the curve. When
// a round joins none because each lone sample's nearest neighbour is lone too (a tip of two
// or three samples cut off together, each the other's nearest), the first lone sample that
// can be joined through its nearest sample that is not lone is, and the rounds go on: the
// nearest sample on the curve stands in for the nearest one (sparse_outlines.json's star at 30
// random samples, seed 6; the glyph outlines' tips at 100-1600 points). It can pick a sample of
// another stroke where two pass close (an `R` at 800 points, seed 1).
//
// Only where lone samples are all that is wrong: every other sample must have exactly two
// curve edges before, and every lone sample must be joined; otherwise the labels stay as they
// are. Each relabelling leaves every other count unchanged, so the curve is then a 1-manifold
// through every sample. Noise and outliers leave samples with other counts or lone samples
// with no such triangle, and keep the paper's labels.
//
// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer); `curve_edges`, its counts per sample (curve_edges_per_sample.h).
// Out: `inner` with the joining triangles relabelled, or as it came; returns how many were.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// The joining alone, for step 8, whose opened pockets can leave a tip lone: `lone` (ascending,
// each with no curve edge under `inner`) joined as above. Out: the relabelled triangles, one
// per lone sample, or nullopt with `inner` as it came if one could not be joined.
std::optional<std::vector<int>> join_lone_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                  std::vector<int> lone);

int join_lone_samples_to_the_curve(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                   const std::vector<int>& curve_edges);

}  // namespace curvebench
