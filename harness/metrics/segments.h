// Line segments, the common currency of the geometric metrics: a true curve, a
// reconstruction and a medial axis all become a list of segments before they are compared.
//
// edge_segments       In: points and index edges into them. Out: one segment per edge.
// closed_polyline_segments  In: the vertices of a closed polyline (the last joins the first).
//                     Out: its segments, the closing one included.
// require_finite      In: segments. Out: nothing, or an exception if one is not finite.
// A point that belongs to no edge (a medial axis reduced to one centre) can be passed as a
// degenerate segment whose two ends coincide; every metric accepts those.
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct Segment2 {
  Point2 source;
  Point2 target;
};

// Throws std::out_of_range if an edge names an index outside `points`.
std::vector<Segment2> edge_segments(std::span<const Point2> points, std::span<const Edge> edges);

std::vector<Segment2> closed_polyline_segments(std::span<const Point2> polyline);

// Throws std::invalid_argument "<what> has a non-finite coordinate" if any segment end is
// NaN or infinite; the metrics call it on their inputs.
void require_finite(std::span<const Segment2> segments, const char* what);

}  // namespace curvebench
