#include "labeling-holes/enclosed_samples.h"

#include <algorithm>

namespace curvebench {

std::vector<int> samples_enclosed_by_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region,
                                            std::span<const int> region_vertices) {
  // A sample with no vertex in the region is not enclosed, so the candidates are the samples
  // of the region's vertices; each one's cell is walked once.
  std::vector<std::uint8_t> looked_at(dv.site_count(), 0);
  std::vector<int> enclosed;
  for (int t : region_vertices) {
    for (int site : dv.triangles[t]) {
      if (looked_at[site] || dv.on_hull[site]) continue;
      looked_at[site] = 1;
      bool inside = true;
      const int first = dv.site_triangle[site];
      int cell = first;
      do {
        inside = region[cell] != 0;
        cell = dv.neighbors[cell][(corner_of_site(dv, cell, site) + 1) % 3];  // counter-clockwise around the site
      } while (inside && cell != first);
      if (inside) enclosed.push_back(site);
    }
  }
  std::sort(enclosed.begin(), enclosed.end());
  return enclosed;
}

}  // namespace curvebench
