#include "voronoi/convex_hull_membership.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvebench {

int ConvexHullMembership::sector_of(Point2 d) {
  // The "diamond angle": d / (|x| + |y|) on the unit diamond, its perimeter walked
  // counter-clockwise from (1, 0) in four quarters of length 1. The zero vector maps to
  // sector 0, whose disk contains it as every disk does.
  const double sum = std::abs(d.x) + std::abs(d.y);
  if (!(sum > 0)) return 0;
  const double p = d.y >= 0 ? (d.x >= 0 ? d.y / sum : 1 - d.x / sum) : (d.x < 0 ? 2 - d.y / sum : 3 + d.x / sum);
  return std::clamp(static_cast<int>(p * (kSectors / 4)), 0, kSectors - 1);
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
  std::vector<double> radius(kSectors, std::numeric_limits<double>::infinity());
  for (int i = 0; i < m; ++i) {
    const Point2 a = dv.sites[hull[i]] - centre_, b = dv.sites[hull[(i + 1) % m]] - centre_;
    const Point2 edge = b - a;
    const double distance = cross(edge, Point2{0, 0} - a) / std::hypot(edge.x, edge.y) - margin;
    if (!(distance > 0)) return;  // the centre is not clearly inside: no disks, every query exact
    // The sectors from a's to b's, counter-clockwise (an edge seen from an interior point spans
    // less than half a turn), one more at each end for the rounding of the pseudo-angle.
    const int first = sector_of(a) - 1, last = sector_of(b) + 1;
    const int span = ((last - first) % kSectors + kSectors) % kSectors;
    for (int k = 0; k <= span; ++k) {
      double& r = radius[((first + k) % kSectors + kSectors) % kSectors];
      r = std::min(r, distance);
    }
  }
  disk_radius_squared_.resize(kSectors);
  for (int s = 0; s < kSectors; ++s) {
    disk_radius_squared_[s] = std::isfinite(radius[s]) ? radius[s] * radius[s] : 0.0;
  }
  smallest_radius_squared_ = *std::min_element(disk_radius_squared_.begin(), disk_radius_squared_.end());
}

}  // namespace curvebench
