// The algorithms known to curvebench. Each registers itself from its own folder, with
//   CURVEBENCH_REGISTER_ALGORITHM(ClassName);
// at namespace scope in one of its .cpp files (ClassName derives from Algorithm and is
// default-constructible); nothing else lists algorithms. algorithms/CMakeLists.txt links
// every folder's objects whole, so no registration is dropped by the linker.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/algorithm.h"

namespace curvebench {

// Every registered algorithm, in order of name.
std::vector<const Algorithm*> all_algorithms();

// The algorithm called `name`; throws InputError naming the known ones if there is none.
const Algorithm& find_algorithm(const std::string& name);

// Adds `algorithm`; throws std::logic_error if its name is taken or not a valid name.
// Returns true, so that a registration can initialise a static.
bool register_algorithm(std::unique_ptr<Algorithm> algorithm);

}  // namespace curvebench

#define CURVEBENCH_REGISTER_ALGORITHM(ClassName) \
  [[maybe_unused]] static const bool curvebench_registered_##ClassName = \
      ::curvebench::register_algorithm(std::make_unique<ClassName>())
