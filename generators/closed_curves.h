// Ground-truth closed curves as dense polylines with their local feature size.
//
// A Scene is one or more disjoint simple curves, each a dense polyline: closed and
// counter-clockwise (the last vertex joins the first), or open (from one end to the other;
// the open families are in open_curves.h), with, at every dense vertex, the local feature
// size: the distance to the medial axis of the whole scene (inner and outer). It is exact
// where a formula exists (circle: its radius) and otherwise measured from the Voronoi
// vertices of the dense polyline itself (see local_feature_size.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct DenseCurve {
  std::vector<Point2> points;  // closed: counter-clockwise, the last joins the first; open: end to end
  bool closed = true;
  std::vector<double> lfs;     // local feature size at each dense point
  std::vector<int> corners;    // dense indices of sharp corners (piecewise-smooth curves), increasing
};

struct Scene {
  std::string name;
  std::vector<DenseCurve> curves;
};

// Families. `dense` is the number of dense vertices per curve (default fine enough for
// epsilon >= 0.05). All are centred at the origin unless placed by a scene builder.
Scene circle_scene(double radius, int dense = 4096);
Scene ellipse_scene(double a, double b, int dense = 8192);
Scene rose_scene(double a, double b, int k, int dense = 8192);             // r = a + b cos(k t)
Scene random_fourier_scene(std::uint64_t seed, int dense = 8192);          // r(t) = 1 + random harmonics, checked simple
Scene disjoint_curves_scene(int count, std::uint64_t seed, int dense = 4096);  // 2-5 disjoint random curves

// Smooth families.
Scene superellipse_scene(double a, double b, double exponent, int dense = 8192);  // |x/a|^e + |y/b|^e = 1; e > 2 rounds a square
Scene dumbbell_scene(double neck_half_width, int dense = 8192);  // Cassini oval: two lobes, neck of the given half-width
// `count` narrow slots cut towards the centre of the unit circle: r(t) = 1 - depth * (sum of
// Gaussian bumps of angular width `width`), depth in (0, 0.9].
Scene concavities_scene(int count, double depth, double width, int dense = 8192);
// A random Fourier curve with a smaller random Fourier curve nested inside it.
Scene nested_curves_scene(std::uint64_t seed, int dense = 4096);
// A random Fourier curve with `count` (1 to 8) disjoint smaller random Fourier curves inside
// it, its holes: the region is the ring between them (even-odd), whose medial axis runs
// between the outer curve and the holes and between holes. Each hole is rotated at random and
// scaled to reach 0.15 to 0.3 from its centre (the outer curve's mean radius is 1), centres
// drawn until every hole keeps 0.1 from the outer curve and from the other holes.
Scene holes_scene(int count, std::uint64_t seed, int dense = 4096);

// Piecewise-smooth families with sharp corners (DenseCurve::corners records them).
Scene star_scene(int points, double inner_ratio, int dense = 8192);  // star polygon, inner radius = ratio * outer
Scene square_scene(double side, int dense = 4096);
Scene l_shape_scene(double arm_width, int dense = 8192);  // L inside the 2x2 square, arms of the given width
// A crescent: the unit disc minus a disc of radius `inner_radius` centred at (offset, 0); two
// horn tips where the arcs meet.
Scene horned_scene(double inner_radius, double offset, int dense = 8192);

// Closed polygons (imported outlines): each ring densified to about `dense` vertices in all,
// every input vertex where the boundary turns by more than 10 degrees kept as a corner. Throws std::invalid_argument
// if a ring has fewer than 3 distinct vertices or the rings are not simple and disjoint.
Scene polygon_scene(std::string name, const std::vector<std::vector<Point2>>& rings, int dense = 8192);

}  // namespace curvebench
