// Many point-in-convex-hull queries against one layer (labeling-holes' step 7 asks it of every
// inner Voronoi vertex), each answered exactly as in_convex_hull answers it, most of them
// without an orientation test.
//
// A point strictly inside a disk that lies inside the hull is inside; only the points the disk
// does not decide go to in_convex_hull. One disk per angular sector about an interior centre
// (the mean of the hull vertices, strictly inside a polygon with three or more corners): its
// radius is the smallest distance from the centre to the line of a hull edge that the sector's
// rays can meet, less a margin far above the rounding of the distances involved. A ray from
// the centre leaves the hull through such an edge, no nearer than that edge's line, so the
// disk is inside. The sectors are equal steps of a pseudo-angle that grows with the angle; a
// point in the smallest of the disks is inside without finding its sector.
//
// In:  the layer (its sites and hull, counter-clockwise); kept by reference.
// Out: contains(q), true if q lies inside or on the boundary of the convex hull of the sites.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

class ConvexHullMembership {
 public:
  explicit ConvexHullMembership(const DelaunayVoronoi& dv);

  bool contains(Point2 q) { return in_a_disk(q) || in_convex_hull(dv_, q, wedge_); }

 private:
  // True only if q lies inside the hull: in the disk of every sector, or of its own.
  bool in_a_disk(Point2 q) const {
    const Point2 d = q - centre_;
    const double squared = dot(d, d);
    return squared < smallest_radius_squared_ ||
           (!disk_radius_squared_.empty() && squared < disk_radius_squared_[sector_of(d)]);
  }

  static constexpr int kSectors = 4096;
  // The sector of direction d, counter-clockwise from the positive x axis (0 for d = 0).
  static int sector_of(Point2 d);

  const DelaunayVoronoi& dv_;
  Point2 centre_{0, 0};
  std::vector<double> disk_radius_squared_;  // per sector; empty where no disk is known (no hull)
  double smallest_radius_squared_ = 0;       // the least of them: its disk lies in every sector's
  int wedge_ = 0;                            // in_convex_hull's hint, carried between queries
};

}  // namespace curvebench
