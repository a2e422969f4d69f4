#include "generators/medial_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

MedialAxis interior_medial_axis(const Scene& scene, int min_separation) {
  std::vector<Point2> all;
  std::vector<int> curve_of, index_on_curve, curve_size;
  for (int c = 0; c < static_cast<int>(scene.curves.size()); ++c) {
    const auto& points = scene.curves[c].points;
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      all.push_back(points[i]);
      curve_of.push_back(c);
      index_on_curve.push_back(i);
    }
    curve_size.push_back(static_cast<int>(points.size()));
  }
  const DelaunayVoronoi dv = build_delaunay_voronoi(all);
  if (dv.dimension != 2 || dv.site_count() != static_cast<int>(all.size())) {
    throw std::invalid_argument(scene.name + ": the medial axis needs distinct vertices that span the plane");
  }
  // Separation of two sites along their curve, in dense vertices (a large number across curves).
  auto separation = [&](int site_a, int site_b) {
    const int a = dv.input_of_site[site_a], b = dv.input_of_site[site_b];
    if (curve_of[a] != curve_of[b]) return 1 << 30;
    const int d = std::abs(index_on_curve[a] - index_on_curve[b]);
    return std::min(d, curve_size[curve_of[a]] - d);
  };

  // Inside or outside by parity: crossing a curve edge flips it, and the unbounded face is
  // outside. A triangle reached with both parities means the curves are not all Delaunay edges.
  const int triangles = dv.triangle_count();
  std::vector<int> parity(triangles, -1);
  std::vector<int> work;
  auto reach = [&](int t, int p) {
    if (parity[t] == -1) {
      parity[t] = p;
      work.push_back(t);
    } else if (parity[t] != p) {
      throw std::invalid_argument(scene.name + ": the dense curves are too sparse to separate inside and outside; use more dense vertices");
    }
  };
  for (int t = 0; t < triangles; ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      if (dv.neighbors[t][corner] != kInfinite) continue;
      reach(t, separation(dv.triangles[t][(corner + 1) % 3], dv.triangles[t][(corner + 2) % 3]) == 1 ? 1 : 0);
    }
  }
  while (!work.empty()) {
    const int t = work.back();
    work.pop_back();
    for (int corner = 0; corner < 3; ++corner) {
      const int across = dv.neighbors[t][corner];
      if (across == kInfinite) continue;
      const bool crosses_curve = separation(dv.triangles[t][(corner + 1) % 3], dv.triangles[t][(corner + 2) % 3]) == 1;
      reach(across, parity[t] ^ (crosses_curve ? 1 : 0));
    }
  }

  MedialAxis axis;
  std::vector<int> vertex_of_triangle(triangles, -1);
  for (int t = 0; t < triangles; ++t) {
    const auto& tri = dv.triangles[t];
    const int widest = std::max({separation(tri[0], tri[1]), separation(tri[1], tri[2]), separation(tri[2], tri[0])});
    if (parity[t] != 1 || widest < min_separation) continue;
    vertex_of_triangle[t] = static_cast<int>(axis.vertices.size());
    axis.vertices.push_back(dv.circumcenters[t]);
    axis.radii.push_back(dv.circumradii[t]);
  }
  for (int t = 0; t < triangles; ++t) {
    if (vertex_of_triangle[t] < 0) continue;
    for (int corner = 0; corner < 3; ++corner) {
      const int across = dv.neighbors[t][corner];
      if (across == kInfinite || across < t || vertex_of_triangle[across] < 0) continue;
      axis.edges.push_back(make_edge(vertex_of_triangle[t], vertex_of_triangle[across]));
    }
  }
  std::sort(axis.edges.begin(), axis.edges.end());
  return axis;
}

MedialAxis circle_medial_axis(Point2 center, double radius) { return {{center}, {radius}, {}}; }

MedialAxis ellipse_medial_axis(double a, double b, int pieces) {
  const bool wide = a >= b;
  const double major = wide ? a : b, minor = wide ? b : a;
  const double half = (major * major - minor * minor) / major;
  MedialAxis axis;
  for (int i = 0; i <= pieces; ++i) {
    const double x = -half + 2 * half * i / pieces;
    // The maximal disc centred at (x, 0) touches where the normal passes through it:
    // cos t = major * x / (major^2 - minor^2).
    const double cos_t = half > 0 ? std::clamp(major * x / (major * major - minor * minor), -1.0, 1.0) : 0.0;
    const double radius = std::hypot(major * cos_t - x, minor * std::sqrt(1 - cos_t * cos_t));
    axis.vertices.push_back(wide ? Point2{x, 0} : Point2{0, x});
    axis.radii.push_back(radius);
    if (i > 0) axis.edges.push_back({i - 1, i});
    if (half == 0) break;  // a circle: the centre alone
  }
  return axis;
}

}  // namespace curvebench
