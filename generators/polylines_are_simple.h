// Simplicity of a set of closed polylines.
//
// In: closed polylines (the last vertex joins the first), each with at least three vertices.
// Out: an empty string if every polyline is simple and no two polylines meet; otherwise a
// short description of the first crossing found, e.g. "curve 0 edge 3 meets curve 0 edge 7".
// Nested polylines are fine (they do not meet). Uses CGAL's exact orientation predicate, on
// a uniform grid of edges, so dense polylines are checked in about linear time.
#pragma once

#include <string>
#include <vector>

#include "core/point.h"

namespace curvebench {

std::string find_polyline_crossing(const std::vector<std::vector<Point2>>& polylines);

}  // namespace curvebench
