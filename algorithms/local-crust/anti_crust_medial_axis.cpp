#include "local-crust/anti_crust_medial_axis.h"

#include <algorithm>
#include <numeric>

namespace curvebench {
namespace {

// Per triangle: 1 inside the crust, 0 outside (breadth-first from the hull triangles).
std::vector<std::uint8_t> inside_by_parity(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  const int triangles = dv.triangle_count();
  std::vector<std::uint8_t> seen(triangles, 0), inside(triangles, 0);
  std::vector<int> queue;
  queue.reserve(triangles);
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3 && !seen[t]; ++k) {
      if (dv.neighbors[t][k] != kInfinite) continue;
      seen[t] = 1;
      inside[t] = crust.is_crust[t][k];  // crossing in from the unbounded face
      queue.push_back(t);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head) {
    const int t = queue[head];
    for (int k = 0; k < 3; ++k) {
      const int u = dv.neighbors[t][k];
      if (u == kInfinite || seen[u]) continue;
      seen[u] = 1;
      inside[u] = inside[t] ^ crust.is_crust[t][k];
      queue.push_back(u);
    }
  }
  return inside;
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

MedialAxis anti_crust_medial_axis(const DelaunayVoronoi& dv, const OneStepCrust& crust) {
  const int triangles = dv.triangle_count();
  const std::vector<std::uint8_t> inside = inside_by_parity(dv, crust);
  auto interior_skeleton_edge = [&](int t, int k) {
    const int other = dv.neighbors[t][k];
    return other != kInfinite && !crust.is_crust[t][k] && inside[t] && inside[other];
  };

  // Union coinciding vertices. The exact co-circularity test only runs on pairs whose computed
  // centres agree within their rounding error bounds.
  std::vector<int> parent(triangles);
  std::iota(parent.begin(), parent.end(), 0);
  bool merged = false;
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (!interior_skeleton_edge(t, k) || other < t) continue;
      const Point2 gap = dv.circumcenters[t] - dv.circumcenters[other];
      const double tolerance = dv.circumcenter_errors[t] + dv.circumcenter_errors[other];
      if (dot(gap, gap) > tolerance * tolerance || !is_degenerate_voronoi_edge(dv, t, k)) continue;
      const int a = find_root(parent, t), b = find_root(parent, other);
      parent[std::max(a, b)] = std::min(a, b);  // the smallest triangle represents its class
      merged = true;
    }
  }

  MedialAxis axis;
  std::vector<int> vertex_of(triangles, -1);
  for (int t = 0; t < triangles; ++t) {
    if (!inside[t]) continue;
    const int root = find_root(parent, t);
    if (vertex_of[root] < 0) {
      vertex_of[root] = static_cast<int>(axis.vertices.size());
      axis.vertices.push_back(dv.circumcenters[root]);
      axis.radii.push_back(dv.circumradii[root]);
    }
    vertex_of[t] = vertex_of[root];
  }
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (!interior_skeleton_edge(t, k) || other < t) continue;
      if (vertex_of[t] != vertex_of[other]) axis.edges.push_back(make_edge(vertex_of[t], vertex_of[other]));
    }
  }
  if (merged) {  // merged classes can be joined by more than one Voronoi edge
    std::sort(axis.edges.begin(), axis.edges.end());
    axis.edges.erase(std::unique(axis.edges.begin(), axis.edges.end()), axis.edges.end());
  }
  return axis;
}

}  // namespace curvebench
