// The "crust" algorithm: the Delaunay edges of the sites that survive adding their Voronoi
// vertices (crust_triangulation.h).
#include "core/registry.h"
#include "crust/crust_triangulation.h"

CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM(
    "crust",
    "Crust: Delaunay edges of the samples plus their Voronoi vertices that join two samples (Amenta, Bern, Eppstein; "
    "GMIP 1998)",
    curvebench::delaunay_edges_with_voronoi_vertices);
