#include "labeling-holes/open_loops_of_three_samples.h"

#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

std::vector<OpenedLoop> open_loops_of_three_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  std::vector<OpenedLoop> loops;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& next = dv.neighbors[t];
    if (!inner[t] || is_inner(inner, next[0]) || is_inner(inner, next[1]) || is_inner(inner, next[2])) continue;
    // Each sample has the loop's two edges; more are those of a curve it lies on.
    int own = 0, shared = -1;
    for (int site : dv.triangles[t]) {
      if (curve_edges_at(dv, inner, site) == 2) {
        ++own;
      } else {
        shared = site;
      }
    }
    if (own >= 2) loops.push_back({t, shared});
  }
  for (const OpenedLoop& loop : loops) inner[loop.triangle] = 0;  // after the scan: no loop neighbours another
  return loops;
}

void close_loops_left_lone(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner, const std::vector<OpenedLoop>& loops) {
  for (const OpenedLoop& loop : loops) {
    bool lone = true;
    for (int site : dv.triangles[loop.triangle]) {
      lone = lone && (site == loop.shared_sample || curve_edges_at(dv, inner, site) == 0);
    }
    // All triangles around a lone sample share a label: outer, the loop's own, and each edge
    // of the loop has a lone end, so the loop comes back as it was; or inner, where step 11
    // took shape-hull's triangles, and nothing changes.
    if (lone) inner[loop.triangle] = 1;
  }
}

}  // namespace curvebench
