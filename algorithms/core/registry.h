// The algorithms known to curvebench. Each registers itself from its own folder, with
//   CURVEBENCH_REGISTER_ALGORITHM(ClassName);
// at namespace scope in one of its .cpp files (ClassName derives from Algorithm and is
// default-constructible), or CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM below; nothing else
// lists algorithms. algorithms/CMakeLists.txt links
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

// The commonest kind, registered without a class of its own: no parameters, and the whole
// output is the curve edges between the Delaunay layer's sites that `edges` computes, timed
// as one phase named after the algorithm.
using DelaunayEdgeFunction = std::vector<Edge> (*)(const DelaunayVoronoi&);
bool register_delaunay_curve_algorithm(std::string name, std::string citation, DelaunayEdgeFunction edges,
                                       CollinearInput collinear = CollinearInput::kRefused);

}  // namespace curvebench

#define CURVEBENCH_REGISTER_ALGORITHM(ClassName) \
  [[maybe_unused]] static const bool curvebench_registered_##ClassName = \
      ::curvebench::register_algorithm(std::make_unique<ClassName>())

// CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM("name", "citation", edge_function[, CollinearInput]);
#define CURVEBENCH_REGISTER_DELAUNAY_CURVE_ALGORITHM(name, citation, ...) \
  [[maybe_unused]] static const bool curvebench_registered_delaunay_curve = \
      ::curvebench::register_delaunay_curve_algorithm(name, citation, __VA_ARGS__)
