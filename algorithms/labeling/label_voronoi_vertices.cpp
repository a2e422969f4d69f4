#include "labeling/label_voronoi_vertices.h"
#include "labeling/walk_steps.h"

#include <algorithm>
#include <numeric>

namespace curvebench {

VoronoiLabels label_voronoi_vertices(const DelaunayVoronoi& dv) {
  const int triangles = dv.triangle_count();
  VoronoiLabels labels;
  labels.inner.assign(triangles, 0);  // Algorithm 2, line 2: every vertex starts outer
  labels.source_vertex.assign(dv.site_count(), kUnpaired);
  for (int s = 0; s < dv.site_count(); ++s) {
    if (dv.on_hull[s]) labels.source_vertex[s] = kInfinite;  // Algorithm 2, line 3
  }

  // Extreme Voronoi vertices. Observation 1 assumes one bounded cell per EVV, but triangles
  // with two hull edges exist, so every triangle with a hull edge is one (gap 6 in README.md).
  // Section 3.3: EVVs inside Conv(P) belong to convex portions (Lemma 5.1) and are inner;
  // a vertex on the hull boundary counts as inside. The others start the walks (Line 4).
  std::vector<int> queue;
  std::vector<std::uint8_t> outside_hull(triangles, 0);
  // Each hull edge lies in one triangle, the first of its start site's fan, so walking the
  // hull meets every EVV (one with two hull edges twice in a row) without scanning all
  // triangles, and meets them in hull order, where each hull test starts next to the last.
  int hull_wedge = 0;
  for (int site : dv.hull) {
    const int t = dv.site_triangle[site];
    if (labels.inner[t] || outside_hull[t]) continue;  // met already, from its other hull edge
    ++labels.extreme_vertices;
    if (in_convex_hull(dv, dv.circumcenters[t], hull_wedge)) {
      labels.inner[t] = 1;
    } else {
      queue.push_back(t);
      outside_hull[t] = 1;
    }
  }
  labels.queued_vertices = static_cast<int>(queue.size());
  // Priorities never change while labeling, so the heap of Algorithm 2 is a sorted list:
  // descending circumradius, ties by triangle index for reproducibility.
  std::sort(queue.begin(), queue.end(), [&](int a, int b) {
    return dv.circumradii[a] > dv.circumradii[b] || (dv.circumradii[a] == dv.circumradii[b] && a < b);
  });

  // Algorithm 1 with an explicit stack instead of recursion (a million samples would
  // overflow the call stack). Neighbours are pushed in reverse so they are taken in the
  // order the recursive calls would make; a vertex is skipped if an earlier branch reached it.
  std::vector<std::uint8_t> visited(triangles, 0);
  std::vector<int> stack;
  for (int root : queue) {
    if (visited[root]) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      if (visited[vertex]) continue;
      visited[vertex] = 1;
      ++labels.visited_vertices;
      // A vertex outside Conv(P) lies outside every polygon on the samples, so no tangent
      // estimate can make it inner: this keeps one poor estimate (at a sharp tip, say) from
      // closing off a whole neighbouring pseudo-concavity before its own walk starts.
      if (!outside_hull[vertex] && crosses_a_tangent_line(dv, labels.source_vertex, vertex)) {
        // Gap 2 (README.md): the walk stops at a vertex that just became inner; walking on
        // would carry the outer label into the interior of the curve.
        labels.inner[vertex] = 1;
        continue;
      }
      // Algorithm 1, lines 1-2. Reached from an outer neighbour, a vertex shares two samples
      // with it that are already paired, so at most one sample is unpaired; it takes this
      // vertex, the first outer vertex found in its cell, as source (walk_steps.h).
      pair_samples_with(dv, labels.source_vertex, vertex);
      for (int k = 2; k >= 0; --k) {
        const int next = dv.neighbors[vertex][k];
        if (next != kInfinite && !visited[next] && !labels.inner[next]) stack.push_back(next);
      }
    }
  }

  // Gap 3 (README.md): a vertex no walk reached lies in the interior of a convex portion (the
  // walks cover every pseudo-concavity and the space between curves), so it is inner.
  for (int t = 0; t < triangles; ++t) {
    if (!visited[t]) labels.inner[t] = 1;
  }
  return labels;
}

}  // namespace curvebench
