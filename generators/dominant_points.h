// The true dominant points of a scene: its corners, or the curvature peaks of smooth curves.
//
// In: a Scene. Out: for each curve with corners (DenseCurve::corners), the corners; for a
// smooth curve, the dense vertices where |curvature| is a strict maximum over the
// max(`window`, n/512) vertices on either side (n dense vertices: rounding noise grows as
// the spacing shrinks) and above the curve's mean |curvature| (the tips and the
// bottoms of concavities: a circle has none, an ellipse the two ends of its major axis); an
// open curve's two ends and its curvature peaks at least the window away from them.
// Curves in order, points in order along each curve.
#pragma once

#include <vector>

#include "core/point.h"
#include "generators/closed_curves.h"

namespace curvebench {

std::vector<Point2> true_dominant_points(const Scene& scene, int window = 16);

}  // namespace curvebench
