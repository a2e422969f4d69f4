// The "labeling" algorithm: incremental Voronoi-vertex labeling (Peethambaran et al. 2019),
// producing the curve, the interior medial axis and the dominant points from one labeling.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_labeling_algorithm();

}  // namespace curvebench
