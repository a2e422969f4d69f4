#include "labeling-holes/enclosed_samples.h"

namespace curvebench {

std::vector<int> samples_enclosed_by_region(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region) {
  std::vector<std::uint8_t> touches_outside(dv.on_hull.begin(), dv.on_hull.end());
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (region[t]) continue;
    for (int site : dv.triangles[t]) touches_outside[site] = 1;
  }
  std::vector<int> enclosed;
  for (int s = 0; s < dv.site_count(); ++s) {
    if (!touches_outside[s] && dv.site_triangle[s] >= 0) enclosed.push_back(s);
  }
  return enclosed;
}

}  // namespace curvebench
