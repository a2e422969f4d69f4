// The "crawl" algorithm: Crawl through Neighbors on the shared Delaunay layer (crawl_edges.h).
#include "core/registry.h"
#include "crawl/crawl_edges.h"

CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM(
    "crawl",
    "Crawl through Neighbors: greedy growth of curves along nearest unused Delaunay neighbours (Parakkat, "
    "Muthuganapathy; CGF 2016)",
    curvebench::crawl_edges,
    // Spec section 2: on collinear input the chain grows along the line (crawl_edges.h).
    curvebench::CollinearInput::kReconstructed);
