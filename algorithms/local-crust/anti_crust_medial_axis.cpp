#include "local-crust/anti_crust_medial_axis.h"

#include "voronoi/voronoi_subgraph.h"

namespace curvebench {
namespace {

// Per triangle: 1 inside the crust, 0 outside (breadth-first from the hull triangles).
std::vector<std::uint8_t> inside_by_parity(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  const int triangles = dv.triangle_count();
  std::vector<std::uint8_t> seen(triangles, 0), inside(triangles, 0);
  std::vector<int> queue;
  queue.reserve(triangles);
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3 && !seen[t]; ++k) {
      if (dv.neighbors[t][k] != kInfinite) continue;
      seen[t] = 1;
      inside[t] = crust.is_crust[t][k];  // crossing in from the unbounded face
      queue.push_back(t);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head) {
    const int t = queue[head];
    for (int k = 0; k < 3; ++k) {
      const int u = dv.neighbors[t][k];
      if (u == kInfinite || seen[u]) continue;
      seen[u] = 1;
      inside[u] = inside[t] ^ crust.is_crust[t][k];
      queue.push_back(u);
    }
  }
  return inside;
}

}  // namespace

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  const std::vector<std::uint8_t> inside = inside_by_parity(dv, crust);
  // Anti-crust edges are the Voronoi edges whose dual Delaunay edge is not crust.
  return voronoi_subgraph(dv, inside, [&](int t, int k) { return !crust.is_crust[t][k]; });
}

}  // namespace curvebench
