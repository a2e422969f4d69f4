// Local feature size of closed polylines, measured from their own Voronoi diagram.
//
// In: dense closed polylines (the curves of one scene, disjoint and simple).
// Out: for every vertex, the distance to the nearest point of the approximate medial axis of
// the whole scene (inner and outer, and between curves). The Voronoi vertices of a dense
// sampling converge to the medial axis, so the approximation is the distance to the nearest
// Voronoi vertex, refined by the distance to the medial-axis Voronoi edges at that vertex
// (those whose dual Delaunay edge is not a polyline edge: the others cross the curve).
// Nearest vertices come from a k-d tree (nearest_point_tree.h). Scenes of more than
// kMaxMeasuredVertices vertices are measured at every k-th vertex (about that many in all)
// and interpolated linearly along arc length in between: the error of the measurement falls
// as the square of the spacing, so 2^17 vertices are plenty, and the cost stays bounded
// (the nearest-vertex search costs about sqrt(vertices) per query along a thin medial axis).
// The error against exact values (circle, ellipse) is stated in tests/cpp/test_generators.cpp.
#pragma once

#include <cstddef>
#include <vector>

#include "core/point.h"

namespace curvebench {

inline constexpr size_t kMaxMeasuredVertices = size_t{1} << 17;

std::vector<std::vector<double>> local_feature_size(const std::vector<std::vector<Point2>>& polylines);

}  // namespace curvebench
