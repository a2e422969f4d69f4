// The two steps every curve family shares: a parametric curve to a dense polyline, and
// dense polylines to a checked Scene with local feature size.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/point.h"
#include "generators/closed_curves.h"

namespace curvebench {

// In: a closed curve t -> point for t in [0, 2 pi) and a vertex count. Out: `dense` points of
// the curve equally spaced in arc length (to about 1e-6 relative), starting at t = 0.
std::vector<Point2> closed_parametric_polyline(const std::function<Point2(double)>& curve, int dense);

// In: closed polylines. Out: a Scene whose curves are these polylines made counter-clockwise
// (the first vertex kept first), consecutive duplicate vertices dropped, and local feature
// size measured (local_feature_size.h) unless `exact_lfs` gives it. Throws
// std::invalid_argument if a polyline has fewer than three vertices or the polylines are
// not simple and disjoint.
Scene make_scene(std::string name, std::vector<std::vector<Point2>> polylines,
                 const std::function<double(Point2)>& exact_lfs = nullptr);

}  // namespace curvebench
