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
  // Coinciding inner vertices (a zero-length Voronoi edge) are found with the exact
  // co-circularity test, run only where the computed centres agree within rounding error.
  auto coincide = [&](int t, int k) {
    const int other = dv.neighbors[t][k];
    const Point2 gap = dv.circumcenters[t] - dv.circumcenters[other];
    const double tolerance = dv.circumcenter_errors[t] + dv.circumcenter_errors[other];
    return dot(gap, gap) <= tolerance * tolerance && is_degenerate_voronoi_edge(dv, t, k);
  };
  auto inner_neighbor = [&](int t, int k) {
    const int other = dv.neighbors[t][k];
    return other != kInfinite && other > t && labels.inner[other];
  };

  std::vector<int> parent;  // union-find over triangles, built only if anything coincides
  for (int t = 0; t < triangles; ++t) {
    if (!labels.inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      if (!inner_neighbor(t, k) || !coincide(t, k)) continue;
      if (parent.empty()) {
        parent.resize(triangles);
        std::iota(parent.begin(), parent.end(), 0);
      }
      const int a = find_root(parent, t), b = find_root(parent, dv.neighbors[t][k]);
      parent[std::max(a, b)] = std::min(a, b);  // the smallest triangle represents its class
    }
  }
  const bool merged = !parent.empty();

  MedialAxis axis;
  std::vector<int> vertex_of(triangles, -1);
  for (int t = 0; t < triangles; ++t) {
    if (!labels.inner[t]) continue;
    const int root = merged ? find_root(parent, t) : t;
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
      if (!inner_neighbor(t, k)) continue;
      const int a = vertex_of[t], b = vertex_of[dv.neighbors[t][k]];
      if (a != b) axis.edges.push_back(make_edge(a, b));
    }
  }
  if (merged) {  // merged classes can be joined by more than one Voronoi edge
    std::sort(axis.edges.begin(), axis.edges.end());
    axis.edges.erase(std::unique(axis.edges.begin(), axis.edges.end()), axis.edges.end());
  }
  return axis;
}

}  // namespace curvebench
