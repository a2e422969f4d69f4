// A part of the Voronoi diagram as a medial-axis graph: the labeler's interior medial axis
// and local crust's interior anti-crust are both "these Voronoi vertices, these edges".
//
// In:  the Delaunay/Voronoi arrays; `keep[t]` nonzero for each Voronoi vertex (triangle) to
//      keep; `keep_edge(t, k)` true for each Voronoi edge to keep, the one dual to the
//      Delaunay edge opposite corner k of triangle t (asked only when both ends are kept).
// Out: the kept vertices with their circumradii and the kept edges between them.
//      Coinciding vertices (co-circular sites, joined by a zero-length kept edge) are merged
//      into one vertex, found with the exact co-circularity test where the computed centres
//      agree within their rounding error bounds.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "core/reconstruction.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

template <class KeepEdge>
MedialAxis voronoi_subgraph(const DelaunayVoronoi& dv, std::span<const std::uint8_t> keep, KeepEdge keep_edge) {
  const int triangles = dv.triangle_count();
  auto kept_edge = [&](int t, int k) {  // each kept edge once, from its smaller triangle
    const int other = dv.neighbors[t][k];
    return other != kInfinite && other > t && keep[t] && keep[other] && keep_edge(t, k);
  };
  auto find_root = [](std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };

  std::vector<int> parent;  // union-find over triangles, built only if anything coincides
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!kept_edge(t, k)) continue;
      const int other = dv.neighbors[t][k];
      const Point2 gap = dv.circumcenters[t] - dv.circumcenters[other];
      const double tolerance = dv.circumcenter_errors[t] + dv.circumcenter_errors[other];
      if (dot(gap, gap) > tolerance * tolerance || !is_degenerate_voronoi_edge(dv, t, k)) continue;
      if (parent.empty()) {
        parent.resize(triangles);
        std::iota(parent.begin(), parent.end(), 0);
      }
      const int a = find_root(parent, t), b = find_root(parent, other);
      parent[std::max(a, b)] = std::min(a, b);  // the smallest triangle represents its class
    }
  }
  const bool merged = !parent.empty();

  MedialAxis axis;
  std::vector<int> vertex_of(triangles, -1);
  for (int t = 0; t < triangles; ++t) {
    if (!keep[t]) continue;
    const int root = merged ? find_root(parent, t) : t;
    if (vertex_of[root] < 0) {
      vertex_of[root] = static_cast<int>(axis.vertices.size());
      axis.vertices.push_back(dv.circumcenters[root]);
      axis.radii.push_back(dv.circumradii[root]);
    }
    vertex_of[t] = vertex_of[root];
  }
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!kept_edge(t, k)) continue;
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
