// libFuzzer target: `reconstruct` with every algorithm. The first byte picks the algorithm,
// the rest is a points file. Each run returns a result whose indices are all in range, or
// throws InputError; anything else (a crash, another exception, a sanitizer report) is a finding.
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/registry.h"
#include "io/points_file.h"

namespace {

void check(bool condition) {
  if (!condition) __builtin_trap();
}

void check_edges(const std::vector<curvebench::Edge>& edges, std::size_t vertex_count) {
  for (const auto& e : edges) check(e[0] >= 0 && e[1] >= 0 && std::size_t(e[0]) < vertex_count && std::size_t(e[1]) < vertex_count);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  if (size < 1) return 0;
  const auto& algorithms = all_algorithms();
  const Algorithm& algorithm = *algorithms[data[0] % algorithms.size()];
  std::vector<Point2> points;
  try {
    points = parse_points(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1), "fuzz");
  } catch (const PointsFileError&) {
    return 0;
  }
  if (points.size() > 3000) return 0;  // keep each run fast; scale is the benchmark's job
  try {
    const auto result = algorithm.reconstruct(points, {});
    if (const auto curve = curve_view(result, points)) {
      check(curve->vertices.size() == (curve->on_input_points ? points.size() : curve->vertices.size()));
      check_edges(std::vector<Edge>(curve->edges.begin(), curve->edges.end()), curve->vertices.size());
      for (const Point2& p : curve->vertices) check(std::isfinite(p.x) && std::isfinite(p.y));
    }
    if (result.medial_axis) {
      check(result.medial_axis->radii.size() == result.medial_axis->vertices.size());
      check_edges(result.medial_axis->edges, result.medial_axis->vertices.size());
    }
    if (result.dominant_points) {
      for (int i : *result.dominant_points) check(i >= 0 && std::size_t(i) < points.size());
    }
  } catch (const InputError&) {
  }
  return 0;
}
