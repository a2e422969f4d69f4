#include "labeling/extract_shapes.h"

#include "voronoi/voronoi_subgraph.h"

namespace curvebench {

std::vector<Edge> extract_curve_edges(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  std::vector<Edge> edges;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& tri = dv.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      const bool other_inner = other != kInfinite && labels.inner[other];
      if (other != kInfinite && other < t) continue;  // each interior edge once
      if (labels.inner[t] != other_inner) edges.push_back(make_edge(tri[(k + 1) % 3], tri[(k + 2) % 3]));
    }
  }
  return edges;
}

MedialAxis extract_interior_medial_axis(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  return voronoi_subgraph(dv, labels.inner, [](int, int) { return true; });
}

}  // namespace curvebench
