#include "labeling-holes/walk_region_from_its_boundary.h"

#include <algorithm>
#include <utility>

#include "labeling/label_voronoi_vertices.h"
#include "labeling/side_of_tangent_line.h"

namespace curvebench {
namespace {

bool faces_outside(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region, int vertex) {
  for (int next : dv.neighbors[vertex]) {
    if (next == kInfinite || !region[next]) return true;
  }
  return false;
}

}  // namespace

std::vector<std::uint8_t> walk_region_from_its_boundary(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region) {
  const int triangles = dv.triangle_count();
  std::vector<int> seeds;
  std::vector<std::uint8_t> is_seed(triangles, 0);
  for (int t = 0; t < triangles; ++t) {
    if (region[t] && faces_outside(dv, region, t)) {
      seeds.push_back(t);
      is_seed[t] = 1;
    }
  }
  std::sort(seeds.begin(), seeds.end(), [&](int a, int b) {
    return dv.circumradii[a] > dv.circumradii[b] || (dv.circumradii[a] == dv.circumradii[b] && a < b);
  });

  std::vector<int> source(dv.site_count(), kUnpaired);
  std::vector<std::uint8_t> visited(triangles, 0), kept(triangles, 0);
  std::vector<int> stack;
  // Definition 5 before pairing, as in label_voronoi_vertices (gap 1 of labeling/README.md).
  auto crosses_a_tangent_line = [&](int vertex) {
    for (int site : dv.triangles[vertex]) {
      const int s = source[site];
      if (s >= 0 && s != vertex && side_of_tangent_line(dv, site, s, vertex) < 0) return true;
    }
    return false;
  };
  for (int root : seeds) {
    stack.assign(1, root);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      if (std::exchange(visited[vertex], std::uint8_t{1})) continue;  // reached by an earlier branch
      // Gap 2 of labeling/README.md: a stopped vertex ends its branch.
      if (!is_seed[vertex] && crosses_a_tangent_line(vertex)) continue;
      kept[vertex] = 1;
      for (int site : dv.triangles[vertex]) {
        const int s = source[site];
        if (s == kUnpaired || dv.circumradii[vertex] > dv.circumradii[s]) source[site] = vertex;
      }
      for (int k = 2; k >= 0; --k) {
        const int next = dv.neighbors[vertex][k];
        if (next != kInfinite && region[next] && !visited[next]) stack.push_back(next);
      }
    }
  }
  return kept;
}

}  // namespace curvebench
