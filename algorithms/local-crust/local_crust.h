// The "local-crust" algorithm (Gold 1999, crust and anti-crust) behind the common interface:
// the one-step crust as the curve and the interior anti-crust as the medial axis, see
// one_step_crust.h and anti_crust_medial_axis.h. No parameters.
#pragma once

#include <memory>

#include "core/algorithm.h"

namespace curvebench {

std::unique_ptr<Algorithm> make_local_crust_algorithm();

}  // namespace curvebench
