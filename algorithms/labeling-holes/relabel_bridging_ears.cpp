#include "labeling-holes/relabel_bridging_ears.h"

#include <algorithm>
#include <limits>

#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

int relabel_bridging_ears(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                          const std::vector<int>& curve_edges) {
  // Relabelling ears only takes edges away, so a sample with fewer than two stays so.
  bool manifold = true;
  for (int count : curve_edges) {
    if (count < 2) return 0;
    manifold = manifold && count == 2;
  }
  if (manifold) return 0;

  auto inner_neighbors_of = [&](int t) {
    int count = 0;
    for (int next : dv.neighbors[t]) count += is_inner(inner, next);
    return count;
  };
  // The longest curve edge at `site` other than those to `a` and `b` (squared; 0 if none), or
  // infinity when the site's cell holds an isolated inner vertex: a closed curve of three
  // samples (a sliver at a corner of a sparse outline), which is not the site's curve.
  auto longest_other_curve_edge = [&](int site, int a, int b) {
    double longest = 0;
    auto consider = [&](int before, int after, int other) {
      if (is_inner(inner, after) && inner_neighbors_of(after) == 0) longest = std::numeric_limits<double>::infinity();
      if (is_inner(inner, before) != is_inner(inner, after) && other != a && other != b) {
        longest = std::max(longest, squared_distance(dv.sites[site], dv.sites[other]));
      }
    };
    // Counter-clockwise around the site; a hull site's fan starts and ends at a hull edge.
    const int first = dv.site_triangle[site];
    if (dv.on_hull[site]) consider(kInfinite, first, dv.triangles[first][(corner_of_site(dv, first, site) + 1) % 3]);
    int t = first;
    do {
      const int corner = corner_of_site(dv, t, site);
      const int next = dv.neighbors[t][(corner + 1) % 3];
      consider(t, next, dv.triangles[t][(corner + 2) % 3]);
      t = next;
    } while (t != kInfinite && t != first);
    return longest;
  };

  std::vector<int> ears;
  std::vector<int> edges_after = curve_edges;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (!inner[t]) continue;
    const auto& neighbors = dv.neighbors[t];
    int inner_neighbors = 0, attached_across = 0;
    for (int k = 0; k < 3; ++k) {
      if (is_inner(inner, neighbors[k])) {
        ++inner_neighbors;
        attached_across = k;
      }
    }
    if (inner_neighbors != 1) continue;  // not an ear
    // An ear attached to another ear is a component of two vertices, no bridge off a region.
    if (inner_neighbors_of(neighbors[attached_across]) < 2) continue;
    // The edge to the inner neighbour is opposite the apex.
    const auto& tri = dv.triangles[t];
    const int apex = tri[attached_across], a = tri[(attached_across + 1) % 3], b = tri[(attached_across + 2) % 3];
    if (curve_edges[apex] <= 2) continue;
    const double ear_shorter = std::min(squared_distance(dv.sites[apex], dv.sites[a]), squared_distance(dv.sites[apex], dv.sites[b]));
    if (ear_shorter <= longest_other_curve_edge(apex, a, b)) continue;  // not the apex's two longest edges
    ears.push_back(t);
    edges_after[apex] -= 2;  // s-a and s-b go; a and b trade one edge for a-b
  }
  // Bridges only where they are all that keeps the curve from being a 1-manifold.
  if (!std::all_of(edges_after.begin(), edges_after.end(), [](int count) { return count == 2; })) return 0;
  for (int t : ears) inner[t] = 0;
  return static_cast<int>(ears.size());
}

}  // namespace curvebench
