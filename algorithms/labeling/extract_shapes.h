// Algorithm 2, lines 9-10 and Section 3.4: the curve, the dominant points and the interior
// medial axis read off the labels.
//
// In:  Delaunay/Voronoi arrays and the final vertex labels.
// Out: curve edges (site pairs) = Delaunay edges whose dual Voronoi edge joins an inner and
//      an outer vertex (a hull edge's dual joins its triangle to the infinite, outer vertex);
//      dominant points (site indices, ascending) = the sites of the label patterns that pass
//      the filter of dominant_points.h, found in the same pass over the label changes;
//      medial axis = the inner Voronoi vertices inside the convex hull of the sites, with
//      their radii, and the Voronoi edges joining two of them. Coinciding vertices (co-circular sites, joined by zero-length
//      Voronoi edges) are merged into one medial-axis vertex.
#pragma once

#include <vector>

#include "core/algorithm.h"
#include "core/reconstruction.h"
#include "labeling/label_voronoi_vertices.h"

namespace curvebench {

struct CurveAndDominantPoints {
  std::vector<Edge> curve_edges;
  std::vector<int> dominant_points;
};

CurveAndDominantPoints extract_curve_and_dominant_points(const DelaunayVoronoi& dv, const VoronoiLabels& labels);

MedialAxis extract_interior_medial_axis(const DelaunayVoronoi& dv, const VoronoiLabels& labels);

// All three, as the result of a labeling algorithm's run().
SiteResult shapes_from_labels(const DelaunayVoronoi& dv, const VoronoiLabels& labels);

}  // namespace curvebench
