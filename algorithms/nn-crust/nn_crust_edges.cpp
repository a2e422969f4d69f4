#include "nn-crust/nn_crust_edges.h"

#include <limits>

namespace curvebench {
namespace {

// Keeps (site, squared distance) if it is nearer than the current best, ties to the smaller
// site. The first candidate is always kept: a squared distance can overflow to infinity
// (coordinates beyond 1e154), and every site must still get a nearest neighbour.
void keep_nearer(int& best, double& best_d2, int site, double d2) {
  if (best < 0 || d2 < best_d2 || (d2 == best_d2 && site < best)) {
    best = site;
    best_d2 = d2;
  }
}

}  // namespace

std::vector<Edge> nn_crust_edges(const DelaunayVoronoi& dv) {
  const int n = dv.site_count();
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // Every Delaunay edge is visited from each triangle containing it (once or twice): cheaper
  // than deduplicating, and harmless for a minimum.
  std::vector<int> nearest(n, -1);
  std::vector<double> nearest_d2(n, kNone);
  for (const auto& tri : dv.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      const double d2 = squared_distance(dv.sites[a], dv.sites[b]);
      keep_nearer(nearest[a], nearest_d2[a], b, d2);
      keep_nearer(nearest[b], nearest_d2[b], a, d2);
    }
  }

  std::vector<int> half(n, -1);
  std::vector<double> half_d2(n, kNone);
  auto consider = [&](int p, int s) {
    const Point2 at = dv.sites[p];
    // angle(q - p, s - p) >= 90 degrees, with q the nearest neighbour of p.
    if (s == nearest[p] || dot(dv.sites[nearest[p]] - at, dv.sites[s] - at) > 0.0) return;
    keep_nearer(half[p], half_d2[p], s, squared_distance(at, dv.sites[s]));
  };
  for (const auto& tri : dv.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      consider(a, b);
      consider(b, a);
    }
  }

  // Each edge once: an edge that both of its ends choose is emitted by the smaller end.
  auto chosen_by = [&](int p, int q) { return nearest[p] == q || half[p] == q; };
  std::vector<Edge> edges;
  edges.reserve(2 * static_cast<size_t>(n));
  for (int p = 0; p < n; ++p) {
    for (const int q : {nearest[p], half[p]}) {
      if (q >= 0 && !(q < p && chosen_by(q, p))) edges.push_back(make_edge(p, q));
    }
  }
  return edges;
}

}  // namespace curvebench
