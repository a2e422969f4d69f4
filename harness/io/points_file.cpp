#include "io/points_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace curvebench {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\v' || c == '\f'; }

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw PointsFileError(name + ":" + std::to_string(line) + ": " + what);
}

double parse_coordinate(std::string_view token, const std::string& name, int line) {
  double value = 0.0;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (!token.empty() && *first == '+') ++first;  // from_chars rejects a leading '+'
  const auto [end, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range) fail(name, line, "coordinate '" + std::string(token) + "' is out of range");
  if (error != std::errc() || end != last) fail(name, line, "'" + std::string(token) + "' is not a number");
  if (!std::isfinite(value)) fail(name, line, "coordinate '" + std::string(token) + "' is not finite");
  return value;
}

}  // namespace

std::vector<Point2> parse_points(std::string_view text, const std::string& name) {
  std::vector<Point2> points;
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

    std::string_view tokens[2];
    int count = 0;
    for (size_t i = 0; i < line.size() && count < 2;) {
      while (i < line.size() && is_separator(line[i])) ++i;
      size_t j = i;
      while (j < line.size() && !is_separator(line[j])) ++j;
      if (j > i) tokens[count++] = line.substr(i, j - i);
      i = j;
    }
    if (count == 0) continue;
    if (count == 1) fail(name, line_number, "expected two coordinates 'x y', found one");
    points.push_back({parse_coordinate(tokens[0], name, line_number), parse_coordinate(tokens[1], name, line_number)});
  }
  return points;
}

std::vector<Point2> read_points_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PointsFileError(path + ": cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw PointsFileError(path + ": read error");
  return parse_points(buffer.str(), path);
}

void write_file_atomically(const std::string& path, std::string_view contents) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw std::runtime_error(path + ": write failed");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace file");
  }
}

void write_points_file(const std::string& path, const std::vector<Point2>& points, const std::string& header_comment) {
  std::string text;
  if (!header_comment.empty()) text += "# " + header_comment + "\n";
  char buffer[64];
  for (const auto& p : points) {
    auto r = std::to_chars(buffer, buffer + sizeof buffer, p.x);
    *r.ptr++ = ' ';
    r = std::to_chars(r.ptr, buffer + sizeof buffer, p.y);
    *r.ptr++ = '\n';
    text.append(buffer, r.ptr);
  }
  write_file_atomically(path, text);
}

}  // namespace curvebench
