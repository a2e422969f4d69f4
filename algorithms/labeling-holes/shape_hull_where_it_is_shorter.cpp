#include "labeling-holes/shape_hull_where_it_is_shorter.h"

#include <cmath>
#include <utility>

#include "labeling-holes/curve_edges_per_sample.h"
#include "labeling-holes/shape_hull_through_every_sample.h"

namespace curvebench {
namespace {

// The total length of the curve edges under `inner`.
double curve_length(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  double length = 0;
  for_each_curve_edge(dv, inner, [&](int a, int b) {
    length += std::hypot(dv.sites[a].x - dv.sites[b].x, dv.sites[a].y - dv.sites[b].y);
  });
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
