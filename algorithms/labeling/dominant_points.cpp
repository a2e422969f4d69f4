#include "labeling/dominant_points.h"
#include "labeling/side_of_tangent_line.h"

namespace curvebench {

bool passes_dominant_point_filter(const DelaunayVoronoi& dv, int centre, int corner) {
  const auto& tri = dv.triangles[centre];
  const int site = tri[corner];
  const Point2 p = dv.sites[site];
  // The terminal across the edge opposite corner `opposite` (one of the two edges at the site).
  auto across = [&](int opposite) {
    const int terminal = dv.neighbors[centre][opposite];
    if (terminal != kInfinite) return side_of_tangent_line(dv, site, centre, terminal) < 0;
    // The infinite vertex, in the direction of its ray: the outward normal of the hull edge.
    // The triangle runs counter-clockwise along its edges with its interior on the left, so
    // the right-hand normal of the edge taken in that direction points out.
    const Point2 d = dv.sites[tri[(opposite + 2) % 3]] - dv.sites[tri[(opposite + 1) % 3]];
    return dot(Point2{d.y, -d.x}, dv.circumcenters[centre] - p) < 0;
  };
  return across((corner + 1) % 3) && across((corner + 2) % 3);
}

}  // namespace curvebench
