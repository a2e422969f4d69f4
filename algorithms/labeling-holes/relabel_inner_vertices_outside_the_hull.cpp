#include "labeling-holes/relabel_inner_vertices_outside_the_hull.h"

#include "labeling-holes/curve_edges_per_sample.h"
#include "voronoi/convex_hull_membership.h"

namespace curvebench {

int relabel_inner_vertices_outside_the_hull(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                            const std::vector<int>& curve_edges) {
  if (!every_sample_has_two_curve_edges(dv, curve_edges)) return 0;
  std::vector<int> outside;
  ConvexHullMembership hull(dv);
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (inner[t] && !hull.contains(dv.circumcenters[t])) outside.push_back(t);
  }
  if (outside.empty()) return 0;
  for (int t : outside) inner[t] = 0;
  if (!every_sample_has_two_curve_edges(dv, curve_edges_per_sample(dv, inner))) {
    for (int t : outside) inner[t] = 1;
    return 0;
  }
  return static_cast<int>(outside.size());
}

}  // namespace curvebench
