// Reading and writing points files: one point per line, `x y` separated by spaces, tabs or
// commas; further columns ignored; `#` starts a comment; LF, CRLF or lone CR line ends.
//
// In: a path (or the text and a name for messages). Out: the points in file order.
// A line that is not two finite numbers throws PointsFileError "<path>:<line>: <what>".
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct PointsFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<Point2> parse_points(std::string_view text, const std::string& name);
std::vector<Point2> read_points_file(const std::string& path);

// Writes `x y` per line with round-trip precision; the file is replaced atomically.
void write_points_file(const std::string& path, const std::vector<Point2>& points, const std::string& header_comment = "");

// Writes `contents` to `path` through a temporary file and a rename, so that a reader never
// sees a partial file. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, std::string_view contents);

}  // namespace curvebench
