// The "crust" algorithm (Amenta, Bern, Eppstein 1998) behind the common interface: the
// curve only, see crust_edges.h. No parameters.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_crust_algorithm();

}  // namespace curvebench
