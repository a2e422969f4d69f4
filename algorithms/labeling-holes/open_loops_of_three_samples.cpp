#include "labeling-holes/open_loops_of_three_samples.h"

#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

std::vector<int> open_loops_of_three_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  auto is_inner = [&](int t) { return t != kInfinite && inner[t] != 0; };
  std::vector<int> loops;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& next = dv.neighbors[t];
    if (!inner[t] || is_inner(next[0]) || is_inner(next[1]) || is_inner(next[2])) continue;
    // Each sample has the loop's two edges; a third is one of a curve the sample lies on.
    bool a_curve_of_its_own = true;
    for (int site : dv.triangles[t]) a_curve_of_its_own = a_curve_of_its_own && curve_edges_at(dv, inner, site) == 2;
    if (a_curve_of_its_own) loops.push_back(t);
  }
  for (int t : loops) inner[t] = 0;  // after the scan: no loop neighbours another
  return loops;
}

void close_loops_left_lone(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner, const std::vector<int>& loops) {
  for (int t : loops) {
    bool lone = true;
    for (int site : dv.triangles[t]) lone = lone && curve_edges_at(dv, inner, site) == 0;
    // All triangles around a lone sample share a label: outer, the loop's own, and the loop
    // comes back as it was; or inner, where step 11 took shape-hull's triangles, and nothing
    // changes.
    if (lone) inner[t] = 1;
  }
}

}  // namespace curvebench
