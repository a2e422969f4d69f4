#include "labeling/dominant_points.h"

#include <cstdint>

namespace curvebench {
namespace {

// Outward normal of the hull edge on the counter-clockwise (`at_end`) or clockwise side of
// the fan of hull site `site` whose first/last triangle is `triangle`.
Point2 hull_edge_outward_normal(const DelaunayVoronoi& dv, int site, int triangle, bool at_end) {
  const int i = corner_of(dv, triangle, site);
  const auto& tri = dv.triangles[triangle];
  // Counter-clockwise hull direction: (corner i+2 -> site) at the end, (site -> corner i+1) at the start.
  const Point2 from = at_end ? dv.sites[tri[(i + 2) % 3]] : dv.sites[site];
  const Point2 to = at_end ? dv.sites[site] : dv.sites[tri[(i + 1) % 3]];
  const Point2 d = to - from;
  return {d.y, -d.x};  // interior on the left, so the right-hand normal points out
}

}  // namespace

std::vector<int> detect_dominant_points(const DelaunayVoronoi& dv, const VoronoiLabels& labels,
                                        std::span<const Edge> curve_edges) {
  // Consecutive vertices of a cell are the two ends of the Voronoi edge dual to a Delaunay
  // edge of the site, so the label changes around a cell are its curve edges. With two
  // changes there are two runs and a run of length one means a label occurs once; only
  // cells where that holds, or with more changes, need the walk below. A site's inner count
  // is the low half of one 64-bit word and its outer count the high half, so each scattered
  // increment touches one cache line, not two.
  const int sites = dv.site_count();
  constexpr std::uint64_t kInner = 1, kOuter = std::uint64_t{1} << 32;
  auto inner_count = [](std::uint64_t counts) { return counts & 0xFFFFFFFFu; };
  auto outer_count = [](std::uint64_t counts) { return counts >> 32; };
  std::vector<std::uint64_t> counts(sites);
  std::vector<int> changes(sites, 0);
  for (int site = 0; site < sites; ++site) counts[site] = dv.on_hull[site] ? kOuter : 0;  // the infinite vertex
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const std::uint64_t one = labels.inner[t] ? kInner : kOuter;
    for (int site : dv.triangles[t]) counts[site] += one;
  }
  for (const auto& e : curve_edges) ++changes[e[0]], ++changes[e[1]];

  std::vector<int> dominant;
  std::vector<int> cell;
  for (int site = 0; site < sites; ++site) {
    if (changes[site] < 2) continue;
    if (changes[site] == 2 && inner_count(counts[site]) != 1 && outer_count(counts[site]) != 1) continue;
    voronoi_cell(dv, site, cell);
    const int m = static_cast<int>(cell.size());
    const bool unbounded = dv.on_hull[site];
    const int cycle = m + (unbounded ? 1 : 0);  // position m is the infinite vertex
    auto is_inner = [&](int pos) { return pos < m && labels.inner[cell[pos]]; };
    const Point2 p = dv.sites[site];
    bool found = false;
    for (int pos = 0; pos < m && !found; ++pos) {
      const int before = (pos + cycle - 1) % cycle, after = (pos + 1) % cycle;
      const bool centre = is_inner(pos);
      if (is_inner(before) == centre || is_inner(after) == centre) continue;
      const int c = cell[pos];
      auto across = [&](int terminal_pos, bool at_end) {
        if (terminal_pos == m) {  // the infinite vertex, in the direction of its ray
          return dot(hull_edge_outward_normal(dv, site, cell[at_end ? m - 1 : 0], at_end), dv.circumcenters[c] - p) < 0;
        }
        return side_of_tangent_line(dv, site, c, cell[terminal_pos]) < 0;
      };
      // The infinite vertex precedes cell[0] (the fan's clockwise start) and follows cell[m-1].
      found = across(before, /*at_end=*/false) && across(after, /*at_end=*/true);
    }
    if (found) dominant.push_back(site);
  }
  return dominant;
}

}  // namespace curvebench
