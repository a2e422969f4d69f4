#include "generators/scene_builder.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "generators/local_feature_size.h"
#include "generators/polylines_are_simple.h"

namespace curvebench {

std::vector<Point2> closed_parametric_polyline(const std::function<Point2(double)>& curve, int dense) {
  if (dense < 3) throw std::invalid_argument("a closed curve needs at least 3 dense vertices");
  // Oversample in the parameter, then place the vertices at equal arc length by inverting
  // the cumulative chord length; the vertices themselves are evaluated on the curve.
  const int fine = 16 * dense;
  const double step = 2.0 * std::numbers::pi / fine;
  std::vector<double> length(fine + 1, 0.0);
  Point2 previous = curve(0.0);
  for (int i = 1; i <= fine; ++i) {
    const Point2 p = curve(i * step);
    length[i] = length[i - 1] + distance(previous, p);
    previous = p;
  }
  std::vector<Point2> points(dense);
  int i = 0;
  for (int j = 0; j < dense; ++j) {
    const double target = length[fine] * j / dense;
    while (length[i + 1] < target) ++i;
    const double span = length[i + 1] - length[i];
    const double fraction = span > 0 ? (target - length[i]) / span : 0.0;
    points[j] = curve((i + fraction) * step);
  }
  return points;
}

Scene make_scene(std::string name, std::vector<std::vector<Point2>> polylines, const std::function<double(Point2)>& exact_lfs) {
  for (auto& poly : polylines) {
    poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    if (poly.size() < 3) throw std::invalid_argument(name + ": a closed curve needs at least 3 distinct vertices");
    double twice_area = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) twice_area += cross(poly[i], poly[(i + 1) % poly.size()]);
    if (twice_area < 0) std::reverse(poly.begin() + 1, poly.end());
  }
  if (const std::string crossing = find_polyline_crossing(polylines); !crossing.empty()) {
    throw std::invalid_argument(name + ": curves are not simple and disjoint (" + crossing + ")");
  }
  Scene scene;
  scene.name = std::move(name);
  std::vector<std::vector<double>> lfs;
  if (exact_lfs) {
    for (const auto& poly : polylines) {
      lfs.emplace_back();
      for (const Point2 p : poly) lfs.back().push_back(exact_lfs(p));
    }
  } else {
    lfs = local_feature_size(polylines);
  }
  for (size_t c = 0; c < polylines.size(); ++c) scene.curves.push_back({std::move(polylines[c]), std::move(lfs[c])});
  return scene;
}

}  // namespace curvebench
