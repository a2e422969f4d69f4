#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

std::vector<int> curve_edges_per_sample(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  std::vector<int> curve_edges(dv.site_count(), 0);
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (!inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int next = dv.neighbors[t][k];
      if (next != kInfinite && inner[next]) continue;
      ++curve_edges[dv.triangles[t][(k + 1) % 3]];
      ++curve_edges[dv.triangles[t][(k + 2) % 3]];
    }
  }
  return curve_edges;
}

}  // namespace curvebench
