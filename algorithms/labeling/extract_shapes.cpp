#include "labeling/extract_shapes.h"

#include <algorithm>

#include "labeling/dominant_points.h"
#include "voronoi/voronoi_subgraph.h"

namespace curvebench {

CurveAndDominantPoints extract_curve_and_dominant_points(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  CurveAndDominantPoints out;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const bool inner = labels.inner[t];
    const auto& neighbors = dv.neighbors[t];
    unsigned changes = 0;  // bit k: the label changes across the edge opposite corner k
    for (int k = 0; k < 3; ++k) {
      const bool other_inner = neighbors[k] != kInfinite && labels.inner[neighbors[k]];
      changes |= static_cast<unsigned>(inner != other_inner) << k;
    }
    if (changes == 0) continue;
    const auto& tri = dv.triangles[t];
    for (int k = 0; k < 3; ++k) {
      // Each interior edge once, from its smaller triangle.
      if ((changes >> k & 1) && (neighbors[k] == kInfinite || neighbors[k] > t)) {
        out.curve_edges.push_back(make_edge(tri[(k + 1) % 3], tri[(k + 2) % 3]));
      }
    }
    if ((changes & (changes - 1)) == 0) continue;  // a pattern centre needs two changes
    for (int corner = 0; corner < 3; ++corner) {
      // The two edges at the site of `corner` are those opposite the other two corners.
      const unsigned at_site = 7u & ~(1u << corner);
      if ((changes & at_site) == at_site && passes_dominant_point_filter(dv, t, corner)) {
        out.dominant_points.push_back(tri[corner]);
      }
    }
  }
  // A sample can be the site of several pattern centres.
  std::sort(out.dominant_points.begin(), out.dominant_points.end());
  out.dominant_points.erase(std::unique(out.dominant_points.begin(), out.dominant_points.end()), out.dominant_points.end());
  return out;
}

MedialAxis extract_interior_medial_axis(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  // Gap 8 (README.md): an inner vertex beyond the convex hull (one no walk reached, inner by
  // gap 3) lies outside every polygon on the samples, so it is no part of an interior medial
  // axis. The hull test gallops from the last query (in_convex_hull).
  std::vector<std::uint8_t> kept(labels.inner.begin(), labels.inner.end());
  int hull_wedge = 0;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (kept[t]) kept[t] = in_convex_hull(dv, dv.circumcenters[t], hull_wedge);
  }
  return voronoi_subgraph(dv, kept, [](int, int) { return true; });
}

SiteResult shapes_from_labels(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  SiteResult result;
  auto [curve, dominant] = extract_curve_and_dominant_points(dv, labels);
  result.curve_edges = std::move(curve);
  result.dominant_points = std::move(dominant);
  result.medial_axis = extract_interior_medial_axis(dv, labels);
  return result;
}

}  // namespace curvebench
