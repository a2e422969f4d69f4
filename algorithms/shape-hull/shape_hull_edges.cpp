#include "shape-hull/shape_hull_edges.h"

#include <algorithm>
#include <numeric>

#include "shape-hull/shape_hull_triangles.h"

namespace curvebench {

std::vector<Edge> shape_hull_edges(const DelaunayVoronoi& dv) {
  const std::vector<std::uint8_t> kept = shape_hull_triangles(dv);
  std::vector<Edge> found;
  // An edge between two kept triangles is interior; one between a kept triangle and a removed
  // one (or the unbounded face) is on the boundary and is seen from its kept side only, so
  // each boundary edge comes out once.
  for (int t = 0; t < static_cast<int>(kept.size()); ++t) {
    if (!kept[t]) continue;
    for (int corner = 0; corner < 3; ++corner) {
      const int other = dv.neighbors[t][corner];
      if (other != kInfinite && kept[other]) continue;
      found.push_back(make_edge(dv.triangles[t][(corner + 1) % 3], dv.triangles[t][(corner + 2) % 3]));
    }
  }
  // Sorted as std::sort would, in linear time: a counting sort by first site, then each
  // site's few edges (two on a simple polygon) by second site.
  std::vector<int> start(dv.site_count() + 1, 0);
  for (const Edge& e : found) ++start[e[0] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Edge> edges(found.size());
  std::vector<int> next = start;
  for (const Edge& e : found) edges[next[e[0]]++] = e;
  for (int site = 0; site < dv.site_count(); ++site) std::sort(edges.begin() + start[site], edges.begin() + start[site + 1]);
  return edges;
}

}  // namespace curvebench
