// Ground-truth closed curves as dense polylines with their local feature size.
//
// A Scene is one or more disjoint simple closed curves, each a dense counter-clockwise
// polyline (the last vertex joins the first) with, at every dense vertex, the local feature
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
  std::vector<Point2> points;  // counter-clockwise, closed implicitly
  std::vector<double> lfs;     // local feature size at each dense point
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

}  // namespace curvebench
