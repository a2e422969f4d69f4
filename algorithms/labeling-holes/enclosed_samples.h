// The evidence that a labeling missed a boundary: samples whose whole Voronoi cell lies in one
// region of Voronoi vertices.
//
// On an epsilon-sample every sample has two poles on opposite sides of the curve (Lemma 3.2
// reads the source vertex as the outer one), so a correct labeling puts vertices of both
// labels in every cell and gives every sample a curve edge. A sample whose cell lies entirely
// in one region (after the paper's labeling: entirely inner) lies on a curve that no walk
// reached, such as the boundary of a hole.
//
// In:  Delaunay/Voronoi arrays; `region[t]` nonzero for the Voronoi vertices of the region,
//      and those vertices listed (`region_vertices`): only their samples are looked at, so a
//      small region costs no pass over all triangles.
// Out: the sites (ascending) all of whose Voronoi vertices are in the region. A hull site's
//      cell holds the infinite vertex, which is in no region, so it is never one of them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> samples_enclosed_by_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region,
                                            std::span<const int> region_vertices);

}  // namespace curvebench
