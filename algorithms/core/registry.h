// The list of algorithms known to curvebench. Adding one is a folder under algorithms/ and
// one line in registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/algorithm.h"

namespace curvebench {

const std::vector<std::unique_ptr<Algorithm>>& all_algorithms();

// The algorithm called `name`; throws InputError naming the known ones if there is none.
const Algorithm& find_algorithm(const std::string& name);

}  // namespace curvebench
