#include "io/points_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/data_lines.h"

namespace curvebench {
namespace {

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
  for_each_data_line(text, [&](const DataLine& line) {
    if (!line.has_second) fail(name, line.number, "expected two coordinates 'x y', found one");
    points.push_back({parse_coordinate(line.first, name, line.number), parse_coordinate(line.second, name, line.number)});
  });
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
