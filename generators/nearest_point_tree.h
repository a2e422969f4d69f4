// Nearest-point queries on a fixed planar point set by a static k-d tree.
//
// In: the points to search. Query: any point. Out: the index of a nearest point (-1 if the
// set is empty). A k-d tree rather than a walk on a Delaunay triangulation: Voronoi vertices
// cluster along the medial axis, often nearly collinear (an ellipse's lie on one segment),
// where a greedy walk meets huge vertex fans and becomes linear per query; the k-d tree
// stays logarithmic on any distribution.
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

class NearestPointTree {
 public:
  explicit NearestPointTree(std::span<const Point2> points);
  int nearest(Point2 query) const;
  // The same, searching only closer than the point `hint` (any index): a good hint, such as
  // the answer for a nearby query, prunes most of the tree.
  int nearest(Point2 query, int hint) const;

 private:
  // A node of the implicit balanced tree covers order_[begin, end), is stored at its middle
  // element and splits there, along x at even depth and y at odd depth. Its bounding box
  // (not just the splitting line) prunes the search: Voronoi vertices along a thin medial
  // axis would otherwise defeat the split-line bound.
  struct Box {
    Point2 low, high;
  };
  std::vector<Point2> points_;
  std::vector<int> order_;
  std::vector<Box> box_at_middle_;
};

}  // namespace curvebench
