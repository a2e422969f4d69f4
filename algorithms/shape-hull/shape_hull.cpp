// The "shape-hull" algorithm: the boundary of the shape-hull graph, sculpted from the shared
// Delaunay layer (shape_hull_triangles.h, shape_hull_edges.h).
#include "core/registry.h"
#include "shape-hull/shape_hull_edges.h"

CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM(
    "shape-hull",
    "Shape-hull: Delaunay triangles sculpted from the hull inwards by circumradius, the boundary as one closed curve "
    "(Peethambaran, Muthuganapathy; Computer-Aided Design 2015)",
    curvebench::shape_hull_edges);
