#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

std::vector<int> curve_edges_per_sample(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  std::vector<int> curve_edges(dv.site_count(), 0);
  for_each_curve_edge(dv, inner, [&](int a, int b) { ++curve_edges[a], ++curve_edges[b]; });
  return curve_edges;
}

}  // namespace curvebench
