// Ground-truth open curves: smooth arcs with two ends, as Scenes of one open dense polyline
// (DenseCurve::closed false, vertices from one end to the other, both ends included).
//
// Local feature size of an open curve C: lfs(p) = the distance from p to the medial axis of
// C seen as a set, i.e. the closure of the points of the plane with two or more nearest
// points on C. An end of a smooth arc is not on that axis: the points beyond the end, up to
// the normal line there, have the end as their only nearest point, so lfs stays positive at
// the ends and an epsilon-sample (Definition 4) exists. What an end adds to the axis are the
// points equidistant from the end and some other part of C (for an arc nearly closing on
// itself, the bisector of the gap between its ends), so near an end lfs is bounded by the
// distance to them. Example, computable by hand: a circular arc of radius R and angle
// theta has as medial axis the ray from the centre through the middle of the missing arc;
// lfs is R everywhere when theta <= 180 degrees, and otherwise R sin(delta) where the angle
// delta, seen from the centre, between p and the middle of the gap is below 90 degrees
// (R sin(theta / 2) at the ends), R elsewhere. The measurement is local_feature_size.h's.
// The interior medial axis of an open curve is empty (it bounds no region).
//
// circular_arc_scene: radius R > 0, angle in (0, 360) degrees, centred at the origin and
//   symmetric about the positive x axis (from -angle/2 to +angle/2).
// elliptic_arc_scene: (a cos t, b sin t) for t from -angle/2 to +angle/2, angle in (0, 360).
// spiral_scene: the Archimedean spiral r = gap (1 + phi / 2 pi), phi from 0 to 2 pi turns:
//   consecutive turns `gap` apart, from radius gap to gap (1 + turns).
// open_random_scene: the random smooth curve of `seed` (fourier_radius.h) over an angle
//   drawn uniformly in [180, 300] degrees from a random start.
// All throw std::invalid_argument for a parameter out of range.
#pragma once

#include <cstdint>

#include "generators/closed_curves.h"

namespace curvebench {

Scene circular_arc_scene(double radius, double angle_degrees, int dense = 4096);
Scene elliptic_arc_scene(double a, double b, double angle_degrees, int dense = 4096);
Scene spiral_scene(double turns, double gap, int dense = 8192);
Scene open_random_scene(std::uint64_t seed, int dense = 4096);

}  // namespace curvebench
