#include "generators/local_feature_size.h"

#include <algorithm>
#include <stdexcept>

#include "generators/nearest_point_tree.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

double distance_to_segment(Point2 q, Point2 a, Point2 b) {
  const Point2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(q - a, ab) / length2, 0.0, 1.0) : 0.0;
  return distance(q, a + t * ab);
}

}  // namespace

std::vector<std::vector<double>> local_feature_size(const std::vector<std::vector<Point2>>& polylines) {
  std::vector<Point2> all;
  std::vector<int> next_along_curve;  // input index of the following vertex of the same polyline
  for (const auto& poly : polylines) {
    const int first = static_cast<int>(all.size());
    const int n = static_cast<int>(poly.size());
    for (int i = 0; i < n; ++i) {
      all.push_back(poly[i]);
      next_along_curve.push_back(first + (i + 1) % n);
    }
  }
  const DelaunayVoronoi dv = build_delaunay_voronoi(all);
  if (dv.dimension != 2 || dv.site_count() != static_cast<int>(all.size())) {
    throw std::invalid_argument("local feature size needs distinct vertices that span the plane");
  }
  auto is_polyline_edge = [&](int site_a, int site_b) {
    const int a = dv.input_of_site[site_a], b = dv.input_of_site[site_b];
    return next_along_curve[a] == b || next_along_curve[b] == a;
  };

  const NearestPointTree nearest_vertex(dv.circumcenters);
  std::vector<std::vector<double>> lfs(polylines.size());
  int input = 0;
  for (size_t c = 0; c < polylines.size(); ++c) {
    lfs[c].resize(polylines[c].size());
    for (size_t i = 0; i < polylines[c].size(); ++i, ++input) {
      const Point2 q = all[input];
      const int t = nearest_vertex.nearest(q);
      const Point2 center = dv.circumcenters[t];
      double d = distance(q, center);
      for (int corner = 0; corner < 3; ++corner) {
        const int across = dv.neighbors[t][corner];
        if (across == kInfinite) continue;
        const auto& tri = dv.triangles[t];
        if (is_polyline_edge(tri[(corner + 1) % 3], tri[(corner + 2) % 3])) continue;
        d = std::min(d, distance_to_segment(q, center, dv.circumcenters[across]));
      }
      lfs[c][i] = d;
    }
  }
  return lfs;
}

}  // namespace curvebench
