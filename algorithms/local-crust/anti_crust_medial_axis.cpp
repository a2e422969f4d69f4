#include "local-crust/anti_crust_medial_axis.h"

#include <numeric>
#include <utility>

#include "voronoi/voronoi_subgraph.h"

namespace curvebench {
namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Per triangle: 1 in the even-odd region of the crust edges (see the header), 0 outside.
std::vector<std::uint8_t> even_odd_region(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  const int triangles = dv.triangle_count();
  const int unbounded = triangles;  // the unbounded face's node
  auto across = [&](int t, int k) { return dv.neighbors[t][k] == kInfinite ? unbounded : dv.neighbors[t][k]; };

  // Faces: triangles joined across non-crust edges.
  std::vector<int> face(triangles + 1);
  std::iota(face.begin(), face.end(), 0);
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (crust.is_crust[t][k]) continue;
      const int a = find_root(face, t), b = find_root(face, across(t, k));
      face[std::max(a, b)] = std::min(a, b);
    }
  }
  for (int node = 0; node <= triangles; ++node) face[node] = find_root(face, node);

  // Face adjacency across the crust edges that separate two different faces.
  std::vector<std::pair<int, int>> links;
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int other = across(t, k);
      if (!crust.is_crust[t][k] || (other != unbounded && other < t)) continue;  // each edge once
      const int a = face[t], b = face[other];
      if (a == b) continue;  // same face on both sides: bounds nothing
      links.emplace_back(a, b);
      links.emplace_back(b, a);
    }
  }
  std::vector<int> first_link(triangles + 2, 0);
  for (const auto& [a, b] : links) ++first_link[a + 1];
  std::partial_sum(first_link.begin(), first_link.end(), first_link.begin());
  std::vector<int> linked(links.size()), filled(first_link.begin(), first_link.end() - 1);
  for (const auto& [a, b] : links) linked[filled[a]++] = b;

  // Depth: breadth-first from the unbounded face, one per crust edge crossed.
  std::vector<int> depth(triangles + 1, -1);
  std::vector<int> queue{face[unbounded]};
  depth[face[unbounded]] = 0;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int f = queue[head];
    for (int i = first_link[f]; i < first_link[f + 1]; ++i) {
      if (depth[linked[i]] >= 0) continue;
      depth[linked[i]] = depth[f] + 1;
      queue.push_back(linked[i]);
    }
  }
  std::vector<std::uint8_t> inside(triangles);
  for (int t = 0; t < triangles; ++t) inside[t] = depth[face[t]] % 2 == 1;
  return inside;
}

}  // namespace

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  // Every vertex kept lies in the region itself (header): no point location is needed.
  const std::vector<std::uint8_t> kept = even_odd_region(dv, crust);
  // Anti-crust edges are the Voronoi edges whose dual Delaunay edge is not crust.
  return voronoi_subgraph(dv, kept, [&](int t, int k) { return !crust.is_crust[t][k]; });
}

}  // namespace curvebench
