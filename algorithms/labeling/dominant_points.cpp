#include "labeling/dominant_points.h"

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

std::vector<int> detect_dominant_points(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  std::vector<int> dominant;
  std::vector<int> cell;
  for (int site = 0; site < dv.site_count(); ++site) {
    voronoi_cell(dv, site, cell);
    const int m = static_cast<int>(cell.size());
    const bool unbounded = dv.on_hull[site];
    const int cycle = m + (unbounded ? 1 : 0);  // position m is the infinite vertex
    if (m == 0 || cycle < 2) continue;
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
