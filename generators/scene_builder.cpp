#include "generators/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "generators/local_feature_size.h"
#include "generators/polylines_are_simple.h"

namespace curvebench {

namespace {

// `dense` points at arc lengths total * j / pieces, j = 0..dense-1, of the curve over
// [0, period]: oversample in the parameter, then place the vertices at equal arc length by
// inverting the cumulative chord length; the vertices themselves are evaluated on the curve.
std::vector<Point2> equal_arc_length_points(const std::function<Point2(double)>& curve, double period, int dense, int pieces) {
  const int fine = 4 * dense;
  const double step = period / fine;
  std::vector<double> length(fine + 1, 0.0);
  Point2 previous = curve(0.0);
  for (int i = 1; i <= fine; ++i) {
    const Point2 p = curve(i * step);
    const Point2 d = p - previous;
    length[i] = length[i - 1] + std::sqrt(dot(d, d));
    previous = p;
  }
  std::vector<Point2> points(dense);
  int i = 0;
  for (int j = 0; j < dense; ++j) {
    const double target = length[fine] * j / pieces;
    while (i + 1 < fine && length[i + 1] < target) ++i;
    const double span = length[i + 1] - length[i];
    const double fraction = span > 0 ? std::min((target - length[i]) / span, 1.0) : 0.0;
    points[j] = curve((i + fraction) * step);
  }
  return points;
}

}  // namespace

std::vector<Point2> closed_parametric_polyline(const std::function<Point2(double)>& curve, int dense) {
  if (dense < 3) throw std::invalid_argument("a closed curve needs at least 3 dense vertices");
  return equal_arc_length_points(curve, 2.0 * std::numbers::pi, dense, dense);
}

std::vector<Point2> open_parametric_polyline(const std::function<Point2(double)>& curve, int dense) {
  if (dense < 3) throw std::invalid_argument("an open curve needs at least 3 dense vertices");
  auto points = equal_arc_length_points(curve, 1.0, dense, dense - 1);
  points.back() = curve(1.0);  // the end exactly, not the end of the chord sum
  return points;
}

Scene make_scene(std::string name, std::vector<DenseCurve> curves, const std::function<double(Point2)>& exact_lfs) {
  std::vector<std::vector<Point2>> polylines;
  std::vector<bool> closed;
  for (auto& curve : curves) {
    auto& poly = curve.points;
    const int n = static_cast<int>(poly.size());
    if (n < 3) throw std::invalid_argument(name + ": a curve needs at least 3 vertices");
    polylines.push_back(poly);
    closed.push_back(curve.closed);
    if (!curve.closed) continue;
    double twice_area = 0.0;
    for (int i = 0; i < n; ++i) twice_area += cross(poly[i], poly[(i + 1) % n]);
    if (twice_area < 0) {
      std::reverse(poly.begin() + 1, poly.end());
      for (int& corner : curve.corners) corner = (n - corner) % n;
      std::sort(curve.corners.begin(), curve.corners.end());
      polylines.back() = poly;
    }
  }
  if (const std::string crossing = find_polyline_crossing(polylines, closed); !crossing.empty()) {
    throw std::invalid_argument(name + ": curves are not simple and disjoint (" + crossing + ")");
  }
  if (exact_lfs) {
    for (auto& curve : curves) {
      curve.lfs.clear();
      for (const Point2 p : curve.points) curve.lfs.push_back(exact_lfs(p));
    }
  } else {
    auto lfs = local_feature_size(polylines, closed);
    for (size_t c = 0; c < curves.size(); ++c) curves[c].lfs = std::move(lfs[c]);
  }
  return Scene{std::move(name), std::move(curves)};
}

std::vector<DenseCurve> densify_polygons(const std::vector<std::vector<Point2>>& polygons, int dense) {
  double perimeter = 0.0;
  for (const auto& polygon : polygons) {
    for (size_t i = 0; i < polygon.size(); ++i) perimeter += distance(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  const double spacing = perimeter / std::max(dense, 3);
  const double min_turn_sine = std::sin(std::numbers::pi / 18);
  std::vector<DenseCurve> curves;
  for (const auto& polygon : polygons) {
    DenseCurve curve;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 previous = polygon[(i + n - 1) % n], here = polygon[i], next = polygon[(i + 1) % n];
      const Point2 in = here - previous, out = next - here;
      const bool turns = std::abs(cross(in, out)) > min_turn_sine * norm(in) * norm(out) || dot(in, out) < 0;
      if (turns) curve.corners.push_back(static_cast<int>(curve.points.size()));
      const int pieces = std::max(1, static_cast<int>(std::ceil(norm(out) / spacing)));
      for (int k = 0; k < pieces; ++k) curve.points.push_back(here + (static_cast<double>(k) / pieces) * out);
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

}  // namespace curvebench
