#include "crust/crust.h"

#include "crust/crust_edges.h"
#include "voronoi/delaunay_curve_algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_crust_algorithm() {
  return std::make_unique<DelaunayCurveAlgorithm>(
      "crust",
      "Crust: Delaunay edges of the samples plus their Voronoi vertices that join two samples "
      "(Amenta, Bern, Eppstein; GMIP 1998)",
      crust_edges);
}

}  // namespace curvebench
