#include "labeling-holes/shape_hull_where_it_is_shorter.h"

#include <cmath>
#include <utility>

#include "labeling-holes/shape_hull_through_every_sample.h"

namespace curvebench {
namespace {

// The total length of the curve edges under `inner`, each counted once from its inner side.
double curve_length(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  double length = 0;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (!inner[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int next = dv.neighbors[t][k];
      if (next != kInfinite && inner[next]) continue;
      const Point2& a = dv.sites[dv.triangles[t][(k + 1) % 3]];
      const Point2& b = dv.sites[dv.triangles[t][(k + 2) % 3]];
      length += std::hypot(a.x - b.x, a.y - b.y);
    }
  }
  return length;
}

}  // namespace

bool take_the_shape_hull_where_it_is_shorter(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  std::vector<std::uint8_t> shape = inner;
  if (!take_the_shape_hull_through_every_sample(dv, shape)) return false;
  // Strictly shorter: on a tie (the same curve, or two of equal length) the repaired labels stay.
  if (!(curve_length(dv, shape) < curve_length(dv, inner))) return false;
  inner = std::move(shape);
  return true;
}

}  // namespace curvebench
