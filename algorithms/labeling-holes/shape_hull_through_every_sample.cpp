#include "labeling-holes/shape_hull_through_every_sample.h"

#include <numeric>
#include <utility>

#include "labeling-holes/curve_edges_per_sample.h"
#include "shape-hull/shape_hull_triangles.h"

namespace curvebench {

bool curve_edges_form_one_connected_curve(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                          const std::vector<int>& curve_edges) {
  // A union-find over the curve edges.
  std::vector<int> parent(dv.site_count());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int s) {
    while (parent[s] != s) s = parent[s] = parent[parent[s]];
    return s;
  };
  for_each_curve_edge(dv, inner, [&](int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent[a] = b;
  });
  int curves = 0;
  for (int s = 0; s < dv.site_count(); ++s) curves += curve_edges[s] > 0 && root(s) == s;
  return curves == 1;
}

bool take_the_shape_hull_through_every_sample(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  if (dv.dimension != 2) return false;
  std::vector<std::uint8_t> shape = shape_hull_triangles(dv);
  if (!every_sample_has_two_curve_edges(dv, curve_edges_per_sample(dv, shape))) return false;
  inner = std::move(shape);
  return true;
}

}  // namespace curvebench
