// Step 8 of labeling-holes: pockets the paper closed off at their mouths, opened again.
//
// Where a pocket (a slot, the gap between a glyph's bowl and its tail, a star's valley) is
// sampled sparsely at its mouth, the paper's walk from outside stops at the mouth's Voronoi
// vertex (Definition 5 against the tangent estimate of an undersampled tip, gap 2 of
// labeling/README.md), the curve closes across the mouth and every vertex of the pocket is
// left inner. The pocket's walls show it: their samples have all-inner cells (the evidence of
// enclosed_samples.h), and the mouth is a curve edge a-b that is the longest edge of its inner
// triangle, in or beside the fan of one of them.
//
// Rule: from each such mouth vertex, in order of decreasing circumradius (Algorithm 2's
// heap), Algorithm 1 walks the inner vertices that have an enclosed sample, as the paper's
// walk would have gone on past the mouth: the mouth vertex is taken outer untested, every
// sample gets a fresh source vertex (the first vertex reached in its cell, moved to a farther
// one, Lemma 3.2), and a vertex strictly across a source's tangent line ends its branch
// (Definition 5). What the walk keeps is relabelled outer only when its boundary is one
// closed curve, that curve but its mouths stands apart (missed_curves_stand_apart.h; a
// corridor's second mouth is tested) and afterwards every sample of its triangles has exactly
// two curve edges (the 1-manifold of an epsilon-sample) and a sample that had none gains
// them: the pocket's walls join the curve, the mouth edge leaves it. A tip the mouth
// had cut off, left with no curve edge, is joined again as step 9 joins a lone sample
// (join_lone_samples_to_the_curve.h); the boundary may take no other curve edge off the
// curve. Otherwise the labels stay as they are.
//
// A pocket opened from one mouth keeps its samples on one curve. One whose samples end on two
// (a joined tip closed into a loop of its own) stays open but is reported: step 11 may then
// take the shape-hull (shape_hull_through_every_sample.h).
//
// In:  Delaunay/Voronoi arrays; `inner` per triangle; the enclosed samples (all-inner cells).
// Out: `inner` with the opened pockets outer; the number of vertices relabelled, and whether
//      a pocket without a second mouth left its samples on two curves.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

struct OpenedPockets {
  int relabelled = 0;
  bool split_a_curve = false;
};

OpenedPockets open_pockets_closed_at_their_mouths(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                        std::span<const int> enclosed_samples);

}  // namespace curvebench
