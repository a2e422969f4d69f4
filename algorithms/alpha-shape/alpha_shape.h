// The "alpha-shape" algorithm behind the common interface: the boundary of CGAL's
// regularized 2D alpha shape (Alpha_shape_2; Edelsbrunner, Kirkpatrick, Seidel 1983).
//
// In:  points; parameters `alpha` (the squared radius of the eraser disk, CGAL's convention,
//      in squared input units; 0 chooses it automatically) and `components`.
// Out: the curve: the regular edges of the regularized alpha shape, i.e. the Delaunay edges
//      with exactly one incident triangle whose circumradius^2 is at most alpha.
//
// Automatic alpha: CGAL's find_optimal_alpha(components), the smallest alpha-value in the
// spectrum (then one step up, as CGAL returns it) at which every sample lies on the
// boundary or in the interior of the shape and the shape has at most `components` solid
// components. Set `components` to the number of disjoint curves in the input; for one
// curve the default 1 fills the region the samples bound, exactly for convex curves and
// with shallow concavities filled in otherwise: alpha shapes are a reference, not a curve
// reconstruction with guarantees.
//
// CGAL's headers are included only by alpha_shape.cpp.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_alpha_shape_algorithm();

}  // namespace curvebench
