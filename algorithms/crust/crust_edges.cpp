#include "crust/crust_edges.h"

#include <cmath>

namespace curvebench {

std::vector<Edge> crust_edges(const DelaunayVoronoi& dv) {
  std::vector<Point2> voronoi_vertices;
  voronoi_vertices.reserve(dv.triangle_count());
  for (const Point2& c : dv.circumcenters) {
    if (std::isfinite(c.x) && std::isfinite(c.y)) voronoi_vertices.push_back(c);
  }
  return delaunay_edges_between_samples(dv.sites, voronoi_vertices);
}

}  // namespace curvebench
