// The true interior medial axis of a scene, as a graph of points with the radius of the
// maximal inscribed disc at each.
//
// interior_medial_axis - In: a Scene (dense simple disjoint closed curves). Out: the Voronoi
//   vertices of the dense vertices that lie inside the region (even-odd over all curves),
//   joined where their Delaunay triangles share an edge that is not a curve edge. Dense
//   sampling leaves a spurious hair at every curvature maximum and corner: a Voronoi vertex
//   is kept only if two of its three samples lie on different curves or at least
//   `min_separation` dense vertices apart along their curve (a hair's samples are neighbours).
//   Throws std::invalid_argument if the dense vertices are too sparse for the curve edges to
//   be Delaunay edges (then inside and outside are not separated).
// circle_medial_axis, ellipse_medial_axis - the exact ones: the centre; the segment between
//   the centres of curvature at the ends of the major axis, cut into `pieces`.
#pragma once

#include <vector>

#include "core/point.h"
#include "core/reconstruction.h"  // MedialAxis: the true axis has the form of a reconstructed one
#include "generators/closed_curves.h"

namespace curvebench {

MedialAxis interior_medial_axis(const Scene& scene, int min_separation = 4);
MedialAxis circle_medial_axis(Point2 center, double radius);
MedialAxis ellipse_medial_axis(double a, double b, int pieces = 64);

}  // namespace curvebench
