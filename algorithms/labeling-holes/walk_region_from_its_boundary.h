// Algorithm 1 of Peethambaran et al. (CGF 2019) run inside a region of Voronoi vertices
// instead of outside the convex hull: the walk that finds the boundaries the paper's walks
// from the EVVs cannot reach (holes, curves nested inside others).
//
// The region is one side of curves already found (after the paper's labeling: the inner
// vertices). Its vertices that face a vertex outside it across a Voronoi edge (or the infinite
// vertex across a hull edge) are the previous labeling's frontier: each became inner by
// Definition 5 against an outer tangent estimate, or is an EVV inside Conv(P) (Section 3.3).
// They play the part of the EVVs: certified on the region's side of the curve, they start
// the walks, in order of decreasing circumradius (Algorithm 2's heap), and are not tested.
// Every sample gets a fresh source vertex, the first region vertex the walk reaches in its
// cell, moved to a farther one when the walk reaches it (the pole estimate, Lemma 3.2, as in
// label_voronoi_vertices). A reached vertex strictly across the estimated tangent line of
// one of its samples (Definition 5, tested before pairing) is stopped and ends its branch;
// the walk never leaves the region.
//
// In:  Delaunay/Voronoi arrays; `region[t]` nonzero for the region's vertices, and those
//      vertices listed in ascending order (`region_vertices`), so that a small region (a
//      nesting level below the first) costs no pass over all triangles.
// Out: the region vertices the walk did not keep (stopped or unreached), ascending; the kept
//      ones stay on the region's side.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> walk_region_from_its_boundary(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region,
                                               std::span<const int> region_vertices);

}  // namespace curvebench
