// FitConnect's order of a neighbourhood along its fitted circle (spec 2.2): the stable sort of
// the neighbours by theta_q = atan2(p_q - c) - atan2(p - c), wrapped once by +-2 pi into
// [-pi, pi], as the authors compute it (in double here).
//
// In:  the fitted centre c (finite), the site p, its neighbours in list order (R_p), and in
//      `order` a guess of their sorted order as indices into `neighbors` (any permutation,
//      e.g. the order of the previous, smaller fit; indices missing from it are appended).
// Out: `order` = the indices sorted by (theta, list index), exactly the stable sort by the
//      theta above; the return value is how many have theta < 0 (they come first).
//
// Why not simply atan2 and std::stable_sort: a sample that keeps growing is re-sorted after
// every growth, and its order barely changes. Here a cheap monotone key of the angle decides
// every comparison whose keys differ by far more than the rounding of either computation
// (the "diamond angle" of (u x d, u . d), u = p - c, d = p_q - c, which rounds to within
// 1e-15 of its exact value while theta rounds to within 3e-15 radians; the key's slope is
// at most 1 per radian); only nearer pairs, and keys near theta = 0 or +-pi, where the
// rounding of the wrap decides the side, compute theta itself. An insertion sort from the
// guess costs the guess's distance from the result, with std::sort (the same strict order)
// once that passes a few moves per element.
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

int sort_by_angle_about(Point2 center, Point2 site, std::span<const Point2> neighbors, std::vector<int>& order);

}  // namespace curvebench
