#include "crust/crust_edges.h"

#include <algorithm>
#include <cmath>

namespace curvebench {

std::vector<Edge> crust_edges(const DelaunayVoronoi& dv) {
  const int samples = dv.site_count();
  std::vector<Point2> joint_points;
  joint_points.reserve(samples + dv.triangle_count());
  joint_points.assign(dv.sites.begin(), dv.sites.end());
  for (const Point2& c : dv.circumcenters) {
    if (std::isfinite(c.x) && std::isfinite(c.y)) joint_points.push_back(c);
  }
  // The samples are distinct and come first, so joint site s < samples is sample s; a Voronoi
  // vertex equal to an earlier point becomes that point's site.
  const DelaunayVoronoi joint = build_delaunay_voronoi(joint_points);

  std::vector<Edge> edges;
  for (int t = 0; t < joint.triangle_count(); ++t) {
    const auto& tri = joint.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int other = joint.neighbors[t][k];
      if (other != kInfinite && other < t) continue;  // each edge once
      const int a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];
      if (a < samples && b < samples) edges.push_back(make_edge(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench
