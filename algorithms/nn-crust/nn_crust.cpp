#include "nn-crust/nn_crust.h"

#include "nn-crust/nn_crust_edges.h"
#include "voronoi/delaunay_curve_algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_nn_crust_algorithm() {
  return std::make_unique<DelaunayCurveAlgorithm>(
      "nn-crust",
      "NN-crust: each sample's nearest-neighbour edge and shortest half-neighbour edge, among Delaunay "
      "edges (Dey, Kumar; SODA 1999)",
      nn_crust_edges);
}

}  // namespace curvebench
