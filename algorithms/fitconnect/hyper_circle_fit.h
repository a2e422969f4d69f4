// The "hyper" algebraic circle fit of Al-Sharadqah and Chernov, "Error analysis for circle
// fitting algorithms" (Electronic Journal of Statistics 3, 2009), as FitConnect uses it
// (spec section 2.1).
//
// In:  m >= 2 points, in the order FitConnect lists a neighbourhood: the sample itself first,
//      then its neighbours by increasing distance. The order matters only in the degenerate
//      (collinear) case.
// Out: centre and radius. The characteristic quartic is solved by Newton's method from 0
//      (at most 99 steps, stopping when a step no longer lowers |P|). When the determinant D
//      falls below the absolute 1e-20 of the authors' code and the points are collinear at
//      their own scale too (D at most 1e-10 of m_z^2; the .cpp says why), the centre is set
//      off the centroid by the unit normal of points 0 -> 1 scaled by 1/sqrt(z) of the last
//      point, as they do; the radius may then be NaN, which FitConnect reads as "not conforming".
//      `on_a_line` says so: the points are (nearly) collinear, and that circle stands for the
//      line only as far as FitConnect's decisions go, not as a curve to move points onto.
#pragma once

#include <span>

#include "core/point.h"

namespace curvebench {

struct FittedCircle {
  Point2 center;
  double radius = 0.0;
  bool on_a_line = false;  // the degenerate branch: the centre and radius are the fallback
};

FittedCircle hyper_circle_fit(std::span<const Point2> points);

}  // namespace curvebench
