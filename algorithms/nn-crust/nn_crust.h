// The "nn-crust" algorithm (Dey, Kumar 1999) behind the common interface: the curve only,
// see nn_crust_edges.h. No parameters.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_nn_crust_algorithm();

}  // namespace curvebench
