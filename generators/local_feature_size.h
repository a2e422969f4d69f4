// Local feature size of polylines, measured from their own Voronoi diagram.
//
// In: dense polylines (the curves of one scene, disjoint and simple), each closed (the last
// vertex joins the first) or open (two ends), as `closed` says (empty: all closed).
// Out: for every vertex, the distance to the nearest point of the approximate medial axis of
// the whole scene (inner and outer, and between curves). The Voronoi vertices of a dense
// sampling converge to the medial axis, so the approximation is the distance to the nearest
// Voronoi vertex, refined by the distance to the medial-axis Voronoi edges at that vertex
// (those whose dual Delaunay edge is not a polyline edge: the others cross the curve).
// Nearest vertices come from a k-d tree (core/nearest_neighbors.h). Scenes of more than
// kMaxMeasuredVertices vertices are measured at every k-th vertex (about that many in all)
// and interpolated linearly along arc length in between: the error of the measurement falls
// as the square of the spacing, so 2^17 vertices are plenty, and the cost stays bounded
// (the nearest-vertex search costs about sqrt(vertices) per query along a thin medial axis).
// The error against exact values (circle, ellipse, circular arc) is stated in
// tests/cpp/test_generators.cpp.
//
// Open curves: the medial axis is that of the curve as a set (open_curves.h), which reaches
// infinity through the gap between the ends, often along a Voronoi ray with no Voronoi
// vertex beyond its start (all samples of a circular arc are co-circular). So in a scene
// with an open curve the distance to every medial-axis Voronoi ray counts too, and the
// Voronoi vertex of a triangle whose three vertices all lie within kEndWindow vertices of
// one end is skipped: it is the centre of the osculating circle at that end, whose only
// nearest curve point is the end itself, not a point of the medial axis. Scenes of closed
// curves only are measured as before (their rays are left out).
#pragma once

#include <cstddef>
#include <vector>

#include "core/point.h"

namespace curvebench {

inline constexpr size_t kMaxMeasuredVertices = size_t{1} << 17;
inline constexpr int kEndWindow = 8;

std::vector<std::vector<double>> local_feature_size(const std::vector<std::vector<Point2>>& polylines,
                                                    const std::vector<bool>& closed = {});

}  // namespace curvebench
