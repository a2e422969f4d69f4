// The lines of a points or edges file that hold data, split into their first two fields.
//
// In:  the file's text: fields separated by spaces, tabs or commas; `#` starts a comment; LF,
//      CRLF or lone CR line ends (harness/README.md, "Points file").
//      `visit` is called for every line with at least one field, in order, with its 1-based
//      line number, its first two fields and whether it has a second (fields past the second
//      are ignored); a visitor rather than a list, so a file of 10^7 points is not held twice.
#pragma once

#include <functional>
#include <string_view>

namespace curvebench {

struct DataLine {
  int number = 0;
  std::string_view first;
  std::string_view second;
  bool has_second = false;
};

void for_each_data_line(std::string_view text, const std::function<void(const DataLine&)>& visit);

}  // namespace curvebench
