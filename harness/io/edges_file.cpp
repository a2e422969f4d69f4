#include "io/edges_file.h"

#include <charconv>

#include "io/data_lines.h"

namespace curvebench {
namespace {

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw EdgesFileError(name + ":" + std::to_string(line) + ": " + what);
}

int parse_index(std::string_view field, const std::string& name, int line, std::size_t vertex_count) {
  long long value = -1;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size()) {
    fail(name, line, "'" + std::string(field) + "' is not a vertex index");
  }
  if (value < 0 || static_cast<unsigned long long>(value) >= vertex_count) {
    fail(name, line, "vertex index " + std::string(field) + " is out of range: there are " + std::to_string(vertex_count) +
                         " vertices, numbered from 0");
  }
  return static_cast<int>(value);
}

}  // namespace

std::vector<Edge> parse_edges(std::string_view text, const std::string& name, std::size_t vertex_count) {
  std::vector<Edge> edges;
  for_each_data_line(text, [&](const DataLine& line) {
    if (!line.has_second) fail(name, line.number, "expected an edge 'i j', found one index");
    const int a = parse_index(line.first, name, line.number, vertex_count);
    const int b = parse_index(line.second, name, line.number, vertex_count);
    if (a == b) fail(name, line.number, "edge " + std::to_string(a) + " " + std::to_string(b) + " joins a vertex to itself");
    edges.push_back(make_edge(a, b));
  });
  return edges;
}

}  // namespace curvebench
