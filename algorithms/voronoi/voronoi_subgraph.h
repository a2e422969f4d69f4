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
#include <memory>
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
  auto coinciding = [&](int t, int k) {  // the kept edge opposite corner k of t has length zero
    const int other = dv.neighbors[t][k];
    const Point2 gap = dv.circumcenters[t] - dv.circumcenters[other];
    const double tolerance = dv.circumcenter_errors[t] + dv.circumcenter_errors[other];
    return dot(gap, gap) <= tolerance * tolerance && is_degenerate_voronoi_edge(dv, t, k);
  };

  auto find_root = [](std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<int> parent;  // union-find over triangles, built only once two vertices coincide
  auto root_of = [&](int t) { return parent.empty() ? t : find_root(parent, t); };

  // One vertex per class of coinciding kept triangles, one edge per kept Voronoi edge between
  // two classes. Before any merge every triangle is its own class; meeting a zero-length edge
  // then stops the collection (false), since classes must be merged first.
  MedialAxis axis;
  // Written for each kept triangle before it is read, so never initialized: a class's root is
  // its smallest triangle, met first in the ascending loop.
  const auto vertex_of = std::make_unique_for_overwrite<int[]>(triangles);
  auto collect = [&] {
    axis = {};
    const auto kept = static_cast<std::size_t>(std::count_if(keep.begin(), keep.end(), [](std::uint8_t k) { return k != 0; }));
    axis.vertices.reserve(kept);
    axis.radii.reserve(kept);
    axis.edges.reserve(kept + kept / 2);
    for (int t = 0; t < triangles; ++t) {
      if (!keep[t]) continue;
      const int root = root_of(t);
      if (root == t) {
        vertex_of[t] = static_cast<int>(axis.vertices.size());
        axis.vertices.push_back(dv.circumcenters[t]);
        axis.radii.push_back(dv.circumradii[t]);
      } else {
        vertex_of[t] = vertex_of[root];
      }
    }
    for (int t = 0; t < triangles; ++t) {
      if (!keep[t]) continue;
      for (int k = 0; k < 3; ++k) {
        if (!kept_edge(t, k)) continue;
        if (parent.empty() && coinciding(t, k)) return false;
        const int a = vertex_of[t], b = vertex_of[dv.neighbors[t][k]];
        if (a != b) axis.edges.push_back(make_edge(a, b));
      }
    }
    return true;
  };
  if (collect()) return axis;

  // Co-circular sites: merge the classes of coinciding vertices and collect again.
  parent.resize(triangles);
  std::iota(parent.begin(), parent.end(), 0);
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!kept_edge(t, k) || !coinciding(t, k)) continue;
      const int a = find_root(parent, t), b = find_root(parent, dv.neighbors[t][k]);
      parent[std::max(a, b)] = std::min(a, b);  // the smallest triangle represents its class
    }
  }
  collect();
  // Merged classes can be joined by more than one Voronoi edge.
  std::sort(axis.edges.begin(), axis.edges.end());
  axis.edges.erase(std::unique(axis.edges.begin(), axis.edges.end()), axis.edges.end());
  return axis;
}

}  // namespace curvebench
