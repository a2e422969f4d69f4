#include "voronoi/circumcenters_in_region.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>

namespace curvebench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

CGAL::Orientation orientation(Point2 a, Point2 b, Point2 q) {
  return CGAL::orientation(Kernel::Point_2(a.x, a.y), Kernel::Point_2(b.x, b.y), Kernel::Point_2(q.x, q.y));
}

// Whether q lies in the closed union of the region's triangles, walking from triangle `start`.
bool in_closed_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> in_region, Point2 q, int start) {
  // The walk's random choices come from a fixed-seed generator: the answer does not depend on
  // them, and the same input always does the same work.
  std::uint32_t state = 0x9e3779b9u ^ static_cast<std::uint32_t>(start);
  auto next_random = [&state] {
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;  // xorshift32
    return state;
  };
  int current = start, previous = kInfinite;
  for (;;) {
    const auto& tri = dv.triangles[current];
    const int first = static_cast<int>(next_random() % 3);
    int across = -1;  // the corner opposite the edge to cross
    for (int i = 0; i < 3 && across < 0; ++i) {
      const int k = (first + i) % 3;
      if (previous != kInfinite && dv.neighbors[current][k] == previous) continue;
      // Triangles are counter-clockwise: q is beyond the edge opposite k if it is to its right.
      if (orientation(dv.sites[tri[(k + 1) % 3]], dv.sites[tri[(k + 2) % 3]], q) == CGAL::RIGHT_TURN) across = k;
    }
    if (across < 0) break;  // q is in the closed triangle
    if (dv.neighbors[current][across] == kInfinite) return false;  // beyond a hull edge
    previous = current;
    current = dv.neighbors[current][across];
  }
  if (in_region[current]) return true;
  const auto& tri = dv.triangles[current];
  for (int k = 0; k < 3; ++k) {
    const int other = dv.neighbors[current][k];
    if (other != kInfinite && in_region[other] &&
        orientation(dv.sites[tri[(k + 1) % 3]], dv.sites[tri[(k + 2) % 3]], q) == CGAL::COLLINEAR) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::uint8_t> circumcenters_in_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> in_region) {
  std::vector<std::uint8_t> inside(dv.triangle_count(), 0);
  for (int t = 0; t < dv.triangle_count(); ++t) {
    inside[t] = in_region[t] && in_closed_region(dv, in_region, dv.circumcenters[t], t);
  }
  return inside;
}

}  // namespace curvebench
