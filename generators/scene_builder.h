// The two steps every curve family shares: a parametric curve to a dense polyline, and
// dense polylines to a checked Scene with local feature size.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/point.h"
#include "generators/closed_curves.h"

namespace curvebench {

// In: a closed curve t -> point for t in [0, 2 pi) and a vertex count. Out: `dense` points of
// the curve equally spaced in arc length (to about 1e-6 relative), starting at t = 0.
std::vector<Point2> closed_parametric_polyline(const std::function<Point2(double)>& curve, int dense);

// In: an open curve t -> point for t in [0, 1] and a vertex count. Out: `dense` points of the
// curve equally spaced in arc length (to about 1e-6 relative), the first at t = 0 and the
// last at t = 1.
std::vector<Point2> open_parametric_polyline(const std::function<Point2(double)>& curve, int dense);

// A curve without corners, local feature size still to be measured.
inline DenseCurve smooth_curve(std::vector<Point2> points, bool closed = true) {
  DenseCurve curve;
  curve.points = std::move(points);
  curve.closed = closed;
  return curve;
}

// In: polylines with points, closed flag (and corners, if any) filled in. Out: a Scene whose
// closed curves are these made counter-clockwise (the first vertex kept first, corners
// renumbered; open ones keep their direction), and local feature size measured
// (local_feature_size.h) unless `exact_lfs` gives it. Throws std::invalid_argument naming
// the scene if a polyline has fewer than three vertices, repeats a vertex, or the polylines
// are not simple and disjoint.
Scene make_scene(std::string name, std::vector<DenseCurve> curves, const std::function<double(Point2)>& exact_lfs = nullptr);

// In: closed polygons (the last vertex joins the first) and the total number of vertices
// wanted. Out: the polygons with vertices added along every edge, spaced at most the
// total perimeter / `dense`; the input vertices are kept, and listed as corners where the
// boundary turns by more than 10 degrees (an outline flattened from smooth arcs turns less).
std::vector<DenseCurve> densify_polygons(const std::vector<std::vector<Point2>>& polygons, int dense);

}  // namespace curvebench
