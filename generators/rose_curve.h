// The rose r = a + b cos(k t): the one formula behind the rose family, the benchmark's
// curve and the tests' hand-made rose samples.
//
// In:  the shape (a > |b| keeps r > 0; k lobes) and the polar angle t.
// Out: the point (r cos t, r sin t), or the outward unit normal there (the tangent turned
//      clockwise, for a counter-clockwise curve).
#pragma once

#include "core/point.h"

namespace curvebench {

Point2 rose_point(double a, double b, int k, double t);
Point2 rose_unit_normal(double a, double b, int k, double t);

}  // namespace curvebench
