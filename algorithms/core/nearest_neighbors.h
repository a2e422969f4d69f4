// Nearest-neighbour queries on a fixed planar point set, on nanoflann's k-d tree.
//
// In:  points (a view: they must outlive the index), distinct or not.
// Out: indices into those points, ordered by increasing distance to the query, exact ties
//      broken by smaller index, so that results never depend on the tree's internal order.
// Distances are compared as squared Euclidean distances in double precision.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

class NearestNeighbors {
 public:
  explicit NearestNeighbors(std::span<const Point2> points);
  ~NearestNeighbors();
  NearestNeighbors(const NearestNeighbors&) = delete;
  NearestNeighbors& operator=(const NearestNeighbors&) = delete;

  // The min(k, size) points nearest to `query`, into `out` (cleared first). A point equal to
  // the query is included (at distance 0). Points whose squared distance to the query
  // overflows to infinity are never returned, so `out` may hold fewer.
  void k_nearest(Point2 query, int k, std::vector<int>& out) const;
  // Every point at distance <= radius from `query`, into `out` (cleared first).
  void within_radius(Point2 query, double radius, std::vector<int>& out) const;
  // The point nearest to `query` (smallest index among equally near ones); -1 if there are none.
  int nearest(Point2 query) const;

  int size() const { return static_cast<int>(points_.size()); }

 private:
  struct Tree;
  std::span<const Point2> points_;
  std::unique_ptr<Tree> tree_;
  void sort_by_distance(Point2 query, std::vector<int>& indices) const;
  void within_squared_distance(Point2 query, double bound, std::vector<int>& out) const;
};

}  // namespace curvebench
