#include "generators/local_feature_size.h"

#include <algorithm>
#include <stdexcept>

#include "core/nearest_neighbors.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

bool is_closed(const std::vector<bool>& closed, size_t c) { return closed.empty() || closed[c]; }

double distance_to_ray(Point2 q, Point2 start, Point2 direction) {
  const double along = std::max(0.0, dot(q - start, direction) / dot(direction, direction));
  return distance(q, start + along * direction);
}

// A Voronoi ray of the medial axis: from `start` along `direction`, to infinity.
struct Ray {
  Point2 start, direction;
};

// The measurement itself, at every vertex.
std::vector<std::vector<double>> measure_local_feature_size(const std::vector<std::vector<Point2>>& polylines,
                                                            const std::vector<bool>& closed) {
  std::vector<Point2> all;
  std::vector<int> next_along_curve;  // input index of the following vertex of the same polyline, -1 at an open end
  std::vector<int> end_near;          // the open end (2 per polyline) within kEndWindow vertices, else -1
  bool any_open = false;
  for (size_t c = 0; c < polylines.size(); ++c) {
    const auto& poly = polylines[c];
    const int first = static_cast<int>(all.size());
    const int n = static_cast<int>(poly.size());
    const bool closed_curve = is_closed(closed, c);
    any_open = any_open || !closed_curve;
    for (int i = 0; i < n; ++i) {
      all.push_back(poly[i]);
      next_along_curve.push_back(closed_curve ? first + (i + 1) % n : i + 1 < n ? first + i + 1 : -1);
      const bool near_first = i < kEndWindow, near_last = n - 1 - i < kEndWindow;
      end_near.push_back(closed_curve || near_first == near_last ? -1 : static_cast<int>(2 * c) + (near_last ? 1 : 0));
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
  // The osculating circle at an open end: all three vertices near the same end.
  auto at_an_end = [&](int t) {
    const int end = end_near[dv.input_of_site[dv.triangles[t][0]]];
    return end >= 0 && std::all_of(dv.triangles[t].begin(), dv.triangles[t].end(),
                                   [&](int site) { return end_near[dv.input_of_site[site]] == end; });
  };
  std::vector<char> kept(dv.triangle_count(), 1);
  std::vector<Point2> kept_centers;
  std::vector<int> triangle_of_kept;
  std::vector<Ray> rays;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (any_open && at_an_end(t)) {
      kept[t] = 0;
      continue;
    }
    kept_centers.push_back(dv.circumcenters[t]);
    triangle_of_kept.push_back(t);
    if (!any_open) continue;
    for (int corner = 0; corner < 3; ++corner) {
      const auto& tri = dv.triangles[t];
      if (dv.neighbors[t][corner] != kInfinite || is_polyline_edge(tri[(corner + 1) % 3], tri[(corner + 2) % 3])) continue;
      // The ray is the bisector of the hull edge, leaving the triangulation (away from the corner opposite it).
      const Point2 a = dv.sites[tri[(corner + 1) % 3]], b = dv.sites[tri[(corner + 2) % 3]];
      const Point2 edge = b - a;
      rays.push_back({dv.circumcenters[t], Point2{edge.y, -edge.x}});
    }
  }

  // A k-d tree rather than a walk on a triangulation: Voronoi vertices cluster along the
  // medial axis, often nearly collinear (an ellipse's lie on one segment), where a greedy
  // walk meets huge vertex fans.
  const NearestNeighbors nearest_vertex(kept_centers);
  std::vector<std::vector<double>> lfs(polylines.size());
  int input = 0;
  for (size_t c = 0; c < polylines.size(); ++c) {
    lfs[c].resize(polylines[c].size());
    for (size_t i = 0; i < polylines[c].size(); ++i, ++input) {
      const Point2 q = all[input];
      const int t = triangle_of_kept[nearest_vertex.nearest(q)];
      const Point2 center = dv.circumcenters[t];
      double d = distance(q, center);
      for (int corner = 0; corner < 3; ++corner) {
        const int across = dv.neighbors[t][corner];
        if (across == kInfinite || !kept[across]) continue;
        const auto& tri = dv.triangles[t];
        if (is_polyline_edge(tri[(corner + 1) % 3], tri[(corner + 2) % 3])) continue;
        d = std::min(d, distance_to_segment(q, center, dv.circumcenters[across]));
      }
      for (const Ray& ray : rays) d = std::min(d, distance_to_ray(q, ray.start, ray.direction));
      lfs[c][i] = d;
    }
  }
  return lfs;
}

}  // namespace

std::vector<std::vector<double>> local_feature_size(const std::vector<std::vector<Point2>>& polylines, const std::vector<bool>& closed) {
  size_t total = 0;
  for (const auto& poly : polylines) total += poly.size();
  const size_t stride = (total + kMaxMeasuredVertices - 1) / kMaxMeasuredVertices;
  if (stride <= 1) return measure_local_feature_size(polylines, closed);

  // Measure at every stride-th vertex (and at the last vertex of an open polyline, its end),
  // then interpolate along arc length in between.
  std::vector<std::vector<Point2>> coarse(polylines.size());
  std::vector<std::vector<size_t>> coarse_index(polylines.size());
  for (size_t c = 0; c < polylines.size(); ++c) {
    for (size_t i = 0; i < polylines[c].size(); i += stride) coarse_index[c].push_back(i);
    if (!is_closed(closed, c) && coarse_index[c].back() != polylines[c].size() - 1) coarse_index[c].push_back(polylines[c].size() - 1);
    for (const size_t i : coarse_index[c]) coarse[c].push_back(polylines[c][i]);
    if (coarse[c].size() < 3) throw std::invalid_argument("local feature size: a curve has too few vertices for its scene");
  }
  const auto coarse_lfs = measure_local_feature_size(coarse, closed);
  std::vector<std::vector<double>> lfs(polylines.size());
  for (size_t c = 0; c < polylines.size(); ++c) {
    const auto& poly = polylines[c];
    const size_t n = poly.size(), m = coarse[c].size();
    const bool closed_curve = is_closed(closed, c);
    lfs[c].resize(n);
    if (!closed_curve) lfs[c][n - 1] = coarse_lfs[c][m - 1];
    for (size_t k = 0; k + (closed_curve ? 0 : 1) < m; ++k) {
      // Runs from one measured vertex to the next; the last run of a closed curve closes it.
      const size_t begin = coarse_index[c][k], end = k + 1 < m ? coarse_index[c][k + 1] : n;
      std::vector<double> along{0.0};
      for (size_t i = begin; i < end; ++i) along.push_back(along.back() + distance(poly[i], poly[(i + 1) % n]));
      const double a = coarse_lfs[c][k], b = coarse_lfs[c][(k + 1) % m];
      for (size_t i = begin; i < end; ++i) lfs[c][i] = a + (b - a) * along[i - begin] / along.back();
    }
  }
  return lfs;
}

}  // namespace curvebench
