#include "voronoi/nearest_site.h"

#include <utility>
#include <vector>

#include "voronoi/cgal_kernel.h"

namespace curvebench {

struct NearestSite::Impl {
  cgal::Delaunay dt;
  mutable cgal::Delaunay::Face_handle hint;  // queries near each other start close by
};

NearestSite::NearestSite(std::span<const Point2> points) : impl_(std::make_unique<Impl>()) {
  std::vector<std::pair<cgal::Point, int>> indexed;
  indexed.reserve(points.size());
  for (int i = 0; i < static_cast<int>(points.size()); ++i) indexed.emplace_back(cgal::Point(points[i].x, points[i].y), i);
  impl_->dt.insert(indexed.begin(), indexed.end());
}

NearestSite::~NearestSite() = default;
NearestSite::NearestSite(NearestSite&&) noexcept = default;
NearestSite& NearestSite::operator=(NearestSite&&) noexcept = default;

int NearestSite::nearest(Point2 query) const {
  if (impl_->dt.number_of_vertices() == 0) return -1;
  const auto v = impl_->dt.nearest_vertex(cgal::Point(query.x, query.y), impl_->hint);
  impl_->hint = v->face();
  return v->info();
}

}  // namespace curvebench
