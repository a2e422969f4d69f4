#include "labeling-holes/relabel_bridging_ears.h"

#include <algorithm>
#include <limits>

namespace curvebench {
namespace {

double squared_distance(Point2 a, Point2 b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

struct CurveEdgesAtSample {
  int count = 0;
  double shortest_squared = std::numeric_limits<double>::infinity();
};

// The curve edges at `site`: the Delaunay edges around its cell whose two sides differ in
// label (the infinite vertex is outer), as labeling/extract_shapes.h reads them.
CurveEdgesAtSample curve_edges_at(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, int site) {
  CurveEdgesAtSample at;
  auto is_inner = [&](int t) { return t != kInfinite && inner[t] != 0; };
  auto count_if_curve_edge = [&](int before, int after, int other_site) {
    if (is_inner(before) == is_inner(after)) return;
    ++at.count;
    at.shortest_squared = std::min(at.shortest_squared, squared_distance(dv.sites[site], dv.sites[other_site]));
  };
  // Counter-clockwise around the site; a hull site's fan starts and ends at a hull edge.
  const int first = dv.site_triangle[site];
  int t = first;
  if (dv.on_hull[site]) {
    const auto& tri = dv.triangles[t];
    const int corner = tri[0] == site ? 0 : (tri[1] == site ? 1 : 2);
    count_if_curve_edge(kInfinite, t, tri[(corner + 1) % 3]);
  }
  do {
    const auto& tri = dv.triangles[t];
    const int corner = tri[0] == site ? 0 : (tri[1] == site ? 1 : 2);
    const int next = dv.neighbors[t][(corner + 1) % 3];
    count_if_curve_edge(t, next, tri[(corner + 2) % 3]);
    t = next;
  } while (t != kInfinite && t != first);
  return at;
}

}  // namespace

int relabel_bridging_ears(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  int relabelled = 0;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    if (!inner[t]) continue;
    const auto& neighbors = dv.neighbors[t];
    int inner_neighbors = 0, attached_across = 0;
    for (int k = 0; k < 3; ++k) {
      if (neighbors[k] != kInfinite && inner[neighbors[k]]) {
        ++inner_neighbors;
        attached_across = k;
      }
    }
    if (inner_neighbors != 1) continue;  // not an ear
    // The edge to the inner neighbour is opposite the apex.
    const auto& tri = dv.triangles[t];
    const int apex = tri[attached_across];
    const CurveEdgesAtSample at_apex = curve_edges_at(dv, inner, apex);
    if (at_apex.count <= 2) continue;
    const double ear_shortest_squared =
        std::min(squared_distance(dv.sites[apex], dv.sites[tri[(attached_across + 1) % 3]]),
                 squared_distance(dv.sites[apex], dv.sites[tri[(attached_across + 2) % 3]]));
    if (ear_shortest_squared <= at_apex.shortest_squared) continue;  // the ear holds the nearest-neighbour edge
    inner[t] = 0;
    ++relabelled;
  }
  return relabelled;
}

}  // namespace curvebench
