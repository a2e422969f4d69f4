#include "io/data_lines.h"

namespace curvebench {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\v' || c == '\f'; }

}  // namespace

void for_each_data_line(std::string_view text, const std::function<void(const DataLine&)>& visit) {
  int line_number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end;
    if (pos < text.size()) {  // one line end: LF, CR or CRLF
      const bool carriage_return = text[pos++] == '\r';
      if (carriage_return && pos < text.size() && text[pos] == '\n') ++pos;
    }
    ++line_number;
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);

    std::string_view fields[2];
    int count = 0;
    for (size_t i = 0; i < line.size() && count < 2;) {
      while (i < line.size() && is_separator(line[i])) ++i;
      size_t j = i;
      while (j < line.size() && !is_separator(line[j])) ++j;
      if (j > i) fields[count++] = line.substr(i, j - i);
      i = j;
    }
    if (count > 0) visit({line_number, fields[0], fields[1], count == 2});
  }
}

}  // namespace curvebench
