#include "labeling/side_of_tangent_line.h"

#include <CGAL/Exact_rational.h>

namespace curvebench {

int exact_side_of_tangent_line(const DelaunayVoronoi& dv, int site, int source, int query) {
  using Q = CGAL::Exact_rational;
  const Point2 p = dv.sites[site];
  auto offset = [&](int triangle, Q& x, Q& y) {  // circumcenter(triangle) - p, exactly
    const auto& tri = dv.triangles[triangle];
    const Q ax(dv.sites[tri[0]].x), ay(dv.sites[tri[0]].y);
    const Q bx = Q(dv.sites[tri[1]].x) - ax, by = Q(dv.sites[tri[1]].y) - ay;
    const Q cx = Q(dv.sites[tri[2]].x) - ax, cy = Q(dv.sites[tri[2]].y) - ay;
    const Q d = 2 * (bx * cy - by * cx);
    const Q b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    x = ax + (cy * b2 - by * c2) / d - Q(p.x);
    y = ay + (bx * c2 - cx * b2) / d - Q(p.y);
  };
  Q sx, sy, qx, qy;
  offset(source, sx, sy);
  offset(query, qx, qy);
  return CGAL::sign(sx * qx + sy * qy);
}

}  // namespace curvebench
