// The even-odd regions of two segment sets, and the area where they differ.
//
// In:  two segment sets, `first` and `second`, each arbitrary: closed polylines (crossing,
//      nested, several), open polylines, dangling or isolated edges, overlapping or
//      degenerate segments.
// Out: the area of the even-odd region of each set and of their symmetric difference.
//
// The even-odd region of a segment set S is defined for every S, as follows.
//  1. Build the planar arrangement of S with exact arithmetic: segments are split where
//     they cross, overlapping pieces are merged. A piece covered by an even number of
//     segments of S is dropped: as in the even-odd rule, two coincident boundaries cancel.
//  2. Take the faces of what remains. A piece with the same face on both of its sides (a
//     dangling edge, an open polyline, a bridge joining two loops) bounds nothing: drop it.
//  3. The depth of a face is the least number of remaining pieces that a path from the face
//     to infinity crosses. The region is the union of the faces of odd depth.
// When the remaining pieces form closed curves (every vertex of the arrangement has even
// degree, as for any set of closed polylines, crossing or nested), every path crosses them
// the same number of times modulo 2, so the region is exactly the classical even-odd fill:
// a square with a square hole is the ring between them. When a vertex branches (a square
// with a spurious diagonal) paths disagree and the least count decides: both triangles have
// depth 1, so the region is the whole square. An open polyline alone has area 0.
//
// Both regions are computed on one overlay arrangement, so the symmetric difference is a sum
// of face areas, exact up to the final conversion of vertex coordinates to double. Throws
// std::invalid_argument if a coordinate is not finite.
#pragma once

#include <span>

#include "metrics/segments.h"

namespace curvebench {

struct EvenOddAreas {
  double first = 0.0;                  // area of the even-odd region of `first`
  double second = 0.0;                 // area of the even-odd region of `second`
  double symmetric_difference = 0.0;   // area covered by exactly one of the two regions
};

EvenOddAreas even_odd_areas(std::span<const Segment2> first, std::span<const Segment2> second);

}  // namespace curvebench
