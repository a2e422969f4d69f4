// How many curve edges each sample has under a labeling of the Voronoi vertices.
//
// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer).
// Out: per site, the number of Delaunay edges at it whose two sides differ in label: its
//      edges in the curve labeling/extract_shapes.h reads from the labels. Each edge is
//      counted once, from its inner side, so the pass touches the inner triangles only.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> curve_edges_per_sample(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner);

// The label of Voronoi vertex t under `inner`: true for inner. The infinite vertex (kInfinite,
// across a hull edge) is outer.
inline bool is_inner(const std::vector<std::uint8_t>& inner, int t) { return t != kInfinite && inner[t] != 0; }

// visit(a, b) for each curve edge, its two sites, once, from its inner side: one pass over the
// inner triangles.
template <class Visit>
void for_each_curve_edge(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Visit&& visit) {
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (!inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int next = dv.neighbors[t][k];
      if (next != kInfinite && inner[next]) continue;
      visit(dv.triangles[t][(k + 1) % 3], dv.triangles[t][(k + 2) % 3]);
    }
  }
}

// visit(end, t, next) for each Delaunay edge site-end at one sample (with a cell: site_triangle
// >= 0) whose two sides t and next have different labels, label(t) for a finite triangle and
// 0 for the infinite vertex (next is kInfinite for a hull edge): a walk around its fan,
// counter-clockwise from site_triangle (for a hull site the first triangle of its open fan).
template <class Label, class Visit>
void for_each_label_change_at(const DelaunayVoronoi& dv, Label&& label, int site, Visit&& visit) {
  const int first = dv.site_triangle[site];
  const int first_corner = corner_of_site(dv, first, site);
  if (dv.neighbors[first][(first_corner + 2) % 3] == kInfinite && label(first) != 0) {
    visit(dv.triangles[first][(first_corner + 1) % 3], first, kInfinite);
  }
  int t = first;
  do {
    const int corner = corner_of_site(dv, t, site);
    const int next = dv.neighbors[t][(corner + 1) % 3];
    if (label(t) != (next == kInfinite ? 0 : label(next))) visit(dv.triangles[t][(corner + 2) % 3], t, next);
    t = next;
  } while (t != kInfinite && t != first);
}

// The curve edges at one sample: the label changes of `inner` (1 inner, 0 outer) around it.
template <class Visit>
void for_each_curve_edge_at(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, int site,
                            Visit&& visit) {
  for_each_label_change_at(dv, [&](int t) { return inner[t] != 0; }, site, visit);
}

// Whether every sample with a cell (site_triangle >= 0) has exactly two curve edges: the
// curve is a 1-manifold through every sample.
inline bool every_sample_has_two_curve_edges(const DelaunayVoronoi& dv, const std::vector<int>& curve_edges) {
  for (int s = 0; s < dv.site_count(); ++s) {
    if (dv.site_triangle[s] >= 0 && curve_edges[s] != 2) return false;
  }
  return true;
}

// The count of one sample.
inline int curve_edges_at(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, int site) {
  int count = 0;
  for_each_curve_edge_at(dv, inner, site, [&](int, int, int) { ++count; });
  return count;
}

}  // namespace curvebench
