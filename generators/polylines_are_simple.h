// Simplicity of a set of polylines.
//
// In: polylines, each closed (the last vertex joins the first; at least three vertices) or
// open (its two ends do not join; at least two vertices), as `closed` says (empty: all closed).
// Out: an empty string if every polyline is simple and no two polylines meet; otherwise a
// short description of the first crossing found, e.g. "curve 0 edge 3 meets curve 0 edge 7".
// Nested polylines are fine (they do not meet). Uses CGAL's exact orientation predicate, on
// a uniform grid of edges, so dense polylines are checked in about linear time.
#pragma once

#include <string>
#include <vector>

#include "core/point.h"

namespace curvebench {

std::string find_polyline_crossing(const std::vector<std::vector<Point2>>& polylines, const std::vector<bool>& closed = {});

}  // namespace curvebench
