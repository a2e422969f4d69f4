// Reading an edges file: one edge per line, two 0-based vertex indices `i j` separated by
// spaces, tabs or commas, with the points file's comments and line ends (data_lines.h).
// What an external algorithm may write instead of a reconstruction JSON.
//
// In:  the text, a name for messages (the file's path or its role) and the number of vertices.
// Out: the edges, each with its smaller index first, in file order.
// A line that is not two different whole numbers in [0, vertex_count) throws EdgesFileError
// "<name>:<line>: <what>".
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct EdgesFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<Edge> parse_edges(std::string_view text, const std::string& name, std::size_t vertex_count);

}  // namespace curvebench
