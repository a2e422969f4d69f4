#include "crust/crust_triangulation.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "voronoi/cgal_kernel.h"

namespace curvebench {

std::vector<Edge> delaunay_edges_with_voronoi_vertices(const DelaunayVoronoi& dv) {
  cgal::IndexedPoints indexed;  // sites, then Voronoi vertices (index -1)
  indexed.reserve(dv.sites.size() + dv.circumcenters.size());
  for (int i = 0; i < dv.site_count(); ++i) indexed.emplace_back(cgal::Point(dv.sites[i].x, dv.sites[i].y), i);
  for (const Point2& center : dv.circumcenters) {
    if (std::isfinite(center.x) && std::isfinite(center.y)) indexed.emplace_back(cgal::Point(center.x, center.y), -1);
  }
  // Triangulating the union afresh, in CGAL's randomized spatial order, is several times
  // faster than inserting the Voronoi vertices into the sites' triangulation: they lie along
  // the medial axes, inside the circumcircles of many long triangles at once.
  cgal::Delaunay dt;
  cgal::insert_in_spatial_order(dt, indexed);  // sites are distinct: a site's vertex keeps its index
  indexed = {};
  // Each edge once, from the face at the lower address; the infinite vertex has no index.
  const auto infinite = dt.infinite_vertex();
  const std::less<const void*> lower_address;
  std::vector<Edge> edges;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
    int index[3];
    for (int i = 0; i < 3; ++i) index[i] = f->vertex(i) == infinite ? -1 : f->vertex(i)->info();
    for (int i = 0; i < 3; ++i) {
      const int a = index[(i + 1) % 3], b = index[(i + 2) % 3];
      if (a >= 0 && b >= 0 && lower_address(&*f, &*f->neighbor(i))) edges.push_back(make_edge(a, b));
    }
  }
  // The face order follows memory addresses, which differ between runs: sorted, the same
  // input gives the same output.
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench
