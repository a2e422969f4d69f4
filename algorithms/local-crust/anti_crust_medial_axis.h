// The interior part of the one-step anti-crust (skeleton), as a medial axis.
//
// In:  the Delaunay/Voronoi arrays and their one-step crust classification.
// Out: the Voronoi vertices of the triangles inside the crust's even-odd region that lie in
//      that region themselves, with their circumradii, and the anti-crust Voronoi edges
//      joining two of them. Coinciding vertices (co-circular samples, joined by zero-length
//      Voronoi edges) are merged into one vertex, as the labeler does.
//
// The region is the even-odd region that the L2 metric scores (harness/metrics/even_odd_areas.h)
// for the crust edges, read off the triangulation: the faces are the sets of triangles joined
// across non-crust edges, plus the unbounded face; a crust edge with the same face on both
// sides (a dangling edge, a bridge, what is left of a curve with a gap) bounds nothing; a
// face is inside when the least number of the remaining crust edges a path to infinity
// crosses is odd. On closed crusts this is the classical parity fill; on a crust with a gap
// it does not depend on the order of a walk, as parity along a breadth-first walk would.
//
// Each kept Voronoi vertex lies in the region, though the triangle it belongs to may be flat
// (three samples on a straight stroke of a glyph): the circumcentres of a face lie in that
// face. A crust edge pq has both opposite angles acute (their sum is below 90 degrees), so
// its diametral disk lies in the two empty circumdisks: pq is a Gabriel edge, and every
// point of it is nearer to p or q than to any other sample. So no Voronoi edge crosses a
// crust edge except its dual. The Voronoi vertices of one face are joined by anti-crust
// edges (duals of its non-crust edges), so they lie in one face of the crust; and a face
// inside has a crust edge on its boundary, whose acute opposite angle puts the inner
// triangle's circumcentre on the face's side, joined to the edge's midpoint by a piece of
// the dual Voronoi edge: that face is the face itself. (The walk-dependent parity used
// before marked triangles of the outer face inside when the crust had a gap, and kept their
// far circumcentres: README.md.)
#pragma once

#include "core/reconstruction.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust);

}  // namespace curvebench
