// Nearest-neighbour queries on a fixed planar point set, backed by a Delaunay triangulation
// (CGAL's, hidden behind this interface so that callers need not include it).
// In: the points to search. Query: any point. Out: index of a nearest point (ties: any).
#pragma once

#include <memory>
#include <span>

#include "core/point.h"

namespace curvebench {

class NearestSite {
 public:
  explicit NearestSite(std::span<const Point2> points);
  ~NearestSite();
  NearestSite(NearestSite&&) noexcept;
  NearestSite& operator=(NearestSite&&) noexcept;

  int nearest(Point2 query) const;  // -1 if the point set is empty

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvebench
