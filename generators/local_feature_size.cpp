#include "generators/local_feature_size.h"

#include <algorithm>
#include <stdexcept>

#include "generators/nearest_point_tree.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

// The measurement itself, at every vertex.
std::vector<std::vector<double>> measure_local_feature_size(const std::vector<std::vector<Point2>>& polylines) {
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
  int previous = 0;  // consecutive vertices have nearby medial points: the last answer is a good hint
  for (size_t c = 0; c < polylines.size(); ++c) {
    lfs[c].resize(polylines[c].size());
    for (size_t i = 0; i < polylines[c].size(); ++i, ++input) {
      const Point2 q = all[input];
      const int t = previous = nearest_vertex.nearest(q, previous);
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

}  // namespace

std::vector<std::vector<double>> local_feature_size(const std::vector<std::vector<Point2>>& polylines) {
  size_t total = 0;
  for (const auto& poly : polylines) total += poly.size();
  const size_t stride = (total + kMaxMeasuredVertices - 1) / kMaxMeasuredVertices;
  if (stride <= 1) return measure_local_feature_size(polylines);

  // Measure at every stride-th vertex, then interpolate along arc length in between.
  std::vector<std::vector<Point2>> coarse(polylines.size());
  for (size_t c = 0; c < polylines.size(); ++c) {
    for (size_t i = 0; i < polylines[c].size(); i += stride) coarse[c].push_back(polylines[c][i]);
    if (coarse[c].size() < 3) throw std::invalid_argument("local feature size: a curve has too few vertices for its scene");
  }
  const auto coarse_lfs = measure_local_feature_size(coarse);
  std::vector<std::vector<double>> lfs(polylines.size());
  for (size_t c = 0; c < polylines.size(); ++c) {
    const auto& poly = polylines[c];
    const size_t n = poly.size(), m = coarse[c].size();
    lfs[c].resize(n);
    for (size_t k = 0; k < m; ++k) {
      const size_t begin = k * stride, end = (k + 1 < m) ? begin + stride : n;  // the last run closes the curve
      std::vector<double> along{0.0};
      for (size_t i = begin; i < end; ++i) along.push_back(along.back() + distance(poly[i], poly[(i + 1) % n]));
      const double a = coarse_lfs[c][k], b = coarse_lfs[c][(k + 1) % m];
      for (size_t i = begin; i < end; ++i) lfs[c][i] = a + (b - a) * along[i - begin] / along.back();
    }
  }
  return lfs;
}

}  // namespace curvebench
