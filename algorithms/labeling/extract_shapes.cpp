#include "labeling/extract_shapes.h"

#include <algorithm>
#include <numeric>

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
  std::sort(edges.begin(), edges.end());
  return edges;
}

namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

MedialAxis extract_interior_medial_axis(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  const int triangles = dv.triangle_count();
  // Union coinciding inner vertices. The exact co-circularity test only runs on pairs whose
  // computed centres are already within rounding distance of each other.
  std::vector<int> parent(triangles);
  std::iota(parent.begin(), parent.end(), 0);
  auto coincide = [&](int t, int k) {
    const int other = dv.neighbors[t][k];
    const double scale = dv.circumradii[t] + norm(dv.circumcenters[t]);
    return distance(dv.circumcenters[t], dv.circumcenters[other]) <= 1e-9 * scale &&
           is_degenerate_voronoi_edge(dv, t, k);
  };
  for (int t = 0; t < triangles; ++t) {
    if (!labels.inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (other == kInfinite || other < t || !labels.inner[other] || !coincide(t, k)) continue;
      const int a = find_root(parent, t), b = find_root(parent, other);
      parent[std::max(a, b)] = std::min(a, b);  // the smallest triangle represents its class
    }
  }

  MedialAxis axis;
  std::vector<int> vertex_of(triangles, -1);
  for (int t = 0; t < triangles; ++t) {
    if (!labels.inner[t]) continue;
    const int root = find_root(parent, t);
    if (vertex_of[root] < 0) {
      vertex_of[root] = static_cast<int>(axis.vertices.size());
      axis.vertices.push_back(dv.circumcenters[root]);
      axis.radii.push_back(dv.circumradii[root]);
    }
    vertex_of[t] = vertex_of[root];
  }
  for (int t = 0; t < triangles; ++t) {
    if (!labels.inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (other == kInfinite || other < t || !labels.inner[other]) continue;
      if (vertex_of[t] != vertex_of[other]) axis.edges.push_back(make_edge(vertex_of[t], vertex_of[other]));
    }
  }
  std::sort(axis.edges.begin(), axis.edges.end());
  axis.edges.erase(std::unique(axis.edges.begin(), axis.edges.end()), axis.edges.end());
  return axis;
}

}  // namespace curvebench
