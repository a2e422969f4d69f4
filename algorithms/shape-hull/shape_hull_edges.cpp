#include "shape-hull/shape_hull_edges.h"

#include <algorithm>

#include "shape-hull/shape_hull_triangles.h"

namespace curvebench {

std::vector<Edge> shape_hull_edges(const DelaunayVoronoi& dv) {
  const std::vector<std::uint8_t> kept = shape_hull_triangles(dv);
  std::vector<Edge> edges;
  // An edge between two kept triangles is interior; one between a kept triangle and a removed
  // one (or the unbounded face) is on the boundary and is seen from its kept side only, so
  // each boundary edge comes out once.
  for (int t = 0; t < static_cast<int>(kept.size()); ++t) {
    if (!kept[t]) continue;
    for (int corner = 0; corner < 3; ++corner) {
      const int other = dv.neighbors[t][corner];
      if (other != kInfinite && kept[other]) continue;
      edges.push_back(make_edge(dv.triangles[t][(corner + 1) % 3], dv.triangles[t][(corner + 2) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench
