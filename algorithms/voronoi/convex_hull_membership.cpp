#include "voronoi/convex_hull_membership.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace curvebench {

int ConvexHullMembership::sector_of(Point2 d) {
  // The diamond angle taken to [0, 4): the unit diamond's perimeter walked counter-clockwise
  // from (1, 0) in four quarters of length 1. The zero vector (NaN) maps to sector 0, whose
  // disk contains it as every disk does.
  double key = diamond_angle(d);
  if (std::isnan(key)) return 0;
  if (key < 0) key += 4;
  return std::clamp(static_cast<int>(key * (kSectors / 4)), 0, kSectors - 1);
}

ConvexHullMembership::ConvexHullMembership(const DelaunayVoronoi& dv) : dv_(dv) {
  const auto& hull = dv.hull;
  const int m = static_cast<int>(hull.size());
  if (dv.dimension < 2 || m < 3) return;
  double scale = 0;
  for (int site : hull) {
    centre_.x += dv.sites[site].x / m;
    centre_.y += dv.sites[site].y / m;
    scale = std::max({scale, std::abs(dv.sites[site].x), std::abs(dv.sites[site].y)});
  }
  // The distances below are exact to a few units in the last place of the coordinates'
  // magnitude; a margin a thousand times that keeps every disk strictly inside.
  const double margin = 1e-12 * scale;
  std::vector<double> radius_squared(kSectors, std::numeric_limits<double>::infinity());
  for (int i = 0; i < m; ++i) {
    const Point2 a = dv.sites[hull[i]] - centre_, b = dv.sites[hull[(i + 1) % m]] - centre_;
    const Point2 edge = b - a;
    const double distance = cross(edge, Point2{0, 0} - a) / norm(edge) - margin;
    if (!(distance > 0)) return;  // the centre is not clearly inside: no disks, every query exact
    // The sectors from a's to b's, counter-clockwise (an edge seen from an interior point spans
    // less than half a turn), one more at each end for the rounding of the pseudo-angle.
    const int first = sector_of(a) - 1, last = sector_of(b) + 1;
    const int span = ((last - first) % kSectors + kSectors) % kSectors;
    for (int k = 0; k <= span; ++k) {
      double& r = radius_squared[((first + k) % kSectors + kSectors) % kSectors];
      r = std::min(r, distance * distance);
    }
  }
  for (double& r : radius_squared) r = std::isfinite(r) ? r : 0.0;  // a sector no edge covers
  disk_radius_squared_ = std::move(radius_squared);
  smallest_radius_squared_ = *std::min_element(disk_radius_squared_.begin(), disk_radius_squared_.end());
}

}  // namespace curvebench
