// The "nn-crust" algorithm: NN-crust on the shared Delaunay layer (nn_crust_edges.h).
#include "core/registry.h"
#include "nn-crust/nn_crust_edges.h"

CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM(
    "nn-crust",
    "NN-crust: each sample's nearest-neighbour edge and shortest half-neighbour edge, among Delaunay edges (Dey, "
    "Kumar; SODA 1999)",
    curvebench::nn_crust_edges);
