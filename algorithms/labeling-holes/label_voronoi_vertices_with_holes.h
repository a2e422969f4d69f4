// Holes and nested curves for the incremental labeling of Peethambaran et al. (CGF 2019):
// the paper's labels, then the regions its walks cannot reach, one nesting level at a time.
//
// The paper's walks start at the EVVs outside Conv(P) (Algorithm 2, line 4), so a boundary
// with no hull bi-tangent (a hole, a curve inside another) is never reached: every vertex
// no walk reaches is labelled inner (gap 3 of labeling/README.md) and the hole is filled.
// Its samples show it: their whole Voronoi cell is inner (enclosed_samples.h), while on an
// epsilon-sample each sample has poles on both sides of the curve.
//
// Rule, applied while such evidence exists. Level 1 is the paper's inner region. Within the
// current region, Algorithm 1 walks from the region's frontier (walk_region_from_its_boundary.h):
// it stays on the region's side and stops at the tangent lines (Definition 5) of the curves
// the paper missed. What the walk does not keep, among the vertices whose three samples are
// enclosed, splits into connected parts (through Voronoi edges); a part whose boundary is a
// set of closed curves through enclosed samples lies across missed curves and takes the
// opposite label (a hole inside the shape, an island inside a hole). A part that also meets
// left-out vertices of found samples (a sparse missed curve pinching a found one) is taken
// only when the taken curves hold every enclosed sample. Any other part keeps the paper's
// label: nothing shows a closed boundary there, and relabelling it would move a curve the
// paper found. The flipped parts are the next level's region, with its own enclosed samples.
// Where the first level takes nothing and evidence is left, pockets the paper closed at their
// mouths are walked from the mouth and opened where their walls then join the curve
// (open_pockets_closed_at_their_mouths.h), and the levels run again; this stands only if no
// evidence is then left.
// Without enclosed samples the labels are the paper's, unchanged. Last, the paper's bridges
// between curves are relabelled: ears through one sample (relabel_bridging_ears.h), then
// corridors outside the convex hull (relabel_inner_vertices_outside_the_hull.h); and samples
// the curve passes by (a sparse sharp tip cut off by its chord, or closed into a loop of three
// samples of its own, open_loops_of_three_samples.h) are joined to it through the triangle at
// their curve edge (join_lone_samples_to_the_curve.h), and corridors the local
// crust test reads as outside are opened (split_curves_joined_across_a_corridor.h). Labels
// that still leave a sample off the curve or on a pinch, on one connected curve, give way to
// the shape-hull's triangles when its curve passes through every sample
// (shape_hull_through_every_sample.h). Repaired labels that make one closed curve through
// every sample give way to them too where the shape-hull's tour is shorter
// (shape_hull_where_it_is_shorter.h).
//
// In:  the Delaunay/Voronoi arrays of samples of one or more closed curves, nested or not.
// Out: the paper's VoronoiLabels (sources and counters from label_voronoi_vertices) with
//      `inner` relabelled as above and its bridging ears outer; the curve, medial axis and
//      dominant points are read from it by labeling/extract_shapes.h.
#pragma once

#include "labeling/label_voronoi_vertices.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

VoronoiLabels label_voronoi_vertices_with_holes(const DelaunayVoronoi& dv);

}  // namespace curvebench
