#include "core/z_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace curvebench {

std::vector<int> z_order(std::span<const Point2> sites) {
  const int n = static_cast<int>(sites.size());
  std::vector<int> order(n);
  if (n == 0) return order;
  double lo_x = sites[0].x, hi_x = lo_x, lo_y = sites[0].y, hi_y = lo_y;
  for (const Point2& q : sites) {
    lo_x = std::min(lo_x, q.x), hi_x = std::max(hi_x, q.x);
    lo_y = std::min(lo_y, q.y), hi_y = std::max(hi_y, q.y);
  }
  int bits = 0;
  while (bits < 15 && (4 << (2 * bits)) < n) ++bits;
  const int side = 1 << bits;
  const double scale = side / std::max(hi_x - lo_x, hi_y - lo_y);
  if (!(scale > 0) || !std::isfinite(scale)) {
    std::iota(order.begin(), order.end(), 0);
    return order;
  }
  auto cell_along = [&](double offset) { return std::min(side - 1, static_cast<int>(offset * scale)); };
  std::vector<int> cell(n), cell_start(side * side + 1, 0);
  for (int i = 0; i < n; ++i) {
    const int x = cell_along(sites[i].x - lo_x), y = cell_along(sites[i].y - lo_y);
    int z = 0;
    for (int b = 0; b < bits; ++b) z |= (((x >> b) & 1) << (2 * b)) | (((y >> b) & 1) << (2 * b + 1));
    cell[i] = z;
    ++cell_start[z + 1];
  }
  std::partial_sum(cell_start.begin(), cell_start.end(), cell_start.begin());
  for (int i = 0; i < n; ++i) order[cell_start[cell[i]]++] = i;
  return order;
}

}  // namespace curvebench
