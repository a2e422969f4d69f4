// Step 12 of labeling-holes: where steps 6-10 repaired the paper's labels into one closed
// curve through every sample, the shape-hull's curve instead if it too is one through every
// sample and is shorter.
//
// Both are then closed polygons through all the samples: two tours of them. For a
// sufficiently dense sample of a closed curve the shortest tour is the curve itself (Giesen,
// "Curve reconstruction, the traveling salesman problem and Menger's theorem on length",
// SoCG 1999; Althaus and Mehlhorn, SIAM J. Computing 2002), so of two tours the shorter is
// the one to defend. The repairs act past the paper's sampling bounds, where a repaired
// curve can be a 1-manifold through every sample and still wrong: the sparse rose at 30
// random samples, seed 7, where the paper leaves 26 and 27 off the curve and the repaired
// curve zigzags between 22 and 25 (9.26 long against shape-hull's true 8.06), and noisy
// stars, whose repaired curves cut across between neighbouring noisy samples. Shape-hull
// (`../shape-hull/`, as in step 11) sculpts from the convex hull and is one closed curve.
//
// The caller (label_voronoi_vertices_with_holes.cpp) decides where: the labels are not the
// paper's own (where they are, and are a 1-manifold, the paper's answer stands), no missed
// curve was taken at step 4, and the labels are one closed curve through every sample. Step
// 11 compares the same two tours where the labels' curve passes through every sample but
// touches itself (pinches, and no other fault).
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer): labels whose curve is one closed curve through every sample.
// Out: true with `inner` set to shape-hull's triangles if under them every sample has exactly
//      two curve edges and their curve is strictly shorter, else false with `inner` as it came.
bool take_the_shape_hull_where_it_is_shorter(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner);

}  // namespace curvebench
