// Incremental labeling of Voronoi vertices: Algorithms 1 and 2 of Peethambaran et al.,
// "Incremental Labeling of Voronoi Vertices for Shape Reconstruction" (CGF 2019), Section 3.
//
// In:  the Delaunay/Voronoi arrays of a point set sampled from one or more closed curves.
// Out: every finite Voronoi vertex (= Delaunay triangle) labelled inner or outer with respect
//      to the unknown curve, and every sample's source Voronoi vertex (SVV, Section 3.2).
//      The infinite Voronoi vertex is outer. The labels are final and consistent: curve,
//      medial axis and dominant points are all read from them.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

inline constexpr int kUnpaired = -2;  // a sample no labeling walk paired with a vertex

struct VoronoiLabels {
  std::vector<std::uint8_t> inner;  // per triangle: 1 inner, 0 outer
  // Per site: the triangle it is paired with (its source Voronoi vertex B_p), kInfinite for
  // samples of unbounded cells (Algorithm 2, line 3), or kUnpaired.
  std::vector<int> source_vertex;
  int extreme_vertices = 0;    // EVVs: triangles with a convex hull edge
  int queued_vertices = 0;     // EVVs outside the convex hull, the walk's starting points
  int visited_vertices = 0;    // vertices the walks reached
};

VoronoiLabels label_voronoi_vertices(const DelaunayVoronoi& dv);

}  // namespace curvebench
