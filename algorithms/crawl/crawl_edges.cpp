#include "crawl/crawl_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace curvebench {
namespace {

// Squared distances between sites after scaling every coordinate by one power of two, which
// maps the largest |coordinate| into [1, 2). The scaling is exact, so every comparison is the
// one between true squared distances, also for inputs whose squares would overflow (beyond
// 1e154) or underflow (below 1e-154) unscaled. Only a set spanning both extremes at once can
// still round distinct distances to equal ones; ties then go to the smaller site index.
class SquaredDistance {
 public:
  explicit SquaredDistance(const std::vector<Point2>& sites) : sites_(sites) {
    double largest = 0.0;
    for (const Point2& p : sites) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    // The clamp keeps the scale itself finite for subnormal or near-overflow coordinates.
    if (largest > 0.0) scale_ = std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1000, 1000));
  }

  double operator()(int a, int b) const {
    const Point2 d = scale_ * sites_[a] - scale_ * sites_[b];
    return dot(d, d);
  }

 private:
  const std::vector<Point2>& sites_;
  double scale_ = 1.0;
};

// The Delaunay neighbours of every site, nearest first (equal distances: smaller site index
// first), in compressed rows: those of site s are sites[begin[s]] .. sites[begin[s + 1] - 1].
// Sorting once serves all three questions of the growth (spec steps 1 and 3): the nearest
// neighbour, the second-nearest, and the nearest unused one, found by a cursor that only
// moves forward because sites never become unused again.
struct SortedNeighbors {
  std::vector<int> begin;
  std::vector<int> sites;
};

SortedNeighbors sorted_delaunay_neighbors(const DelaunayVoronoi& dv, const SquaredDistance& squared_distance) {
  const int n = dv.site_count();
  SortedNeighbors lists;
  lists.begin.reserve(n + 1);
  // A planar triangulation has fewer than 3n edges, each listed from both ends.
  lists.sites.reserve(6 * static_cast<size_t>(n));
  std::vector<std::pair<double, int>> fan;
  for (int s = 0; s < n; ++s) {
    lists.begin.push_back(static_cast<int>(lists.sites.size()));
    fan.clear();
    const int first = dv.site_triangle[s];
    // Counter-clockwise around s: triangle (s, a, b) gives a; the next one shares edge sb. A
    // hull site's walk starts at the clockwise end of its fan (see delaunay_voronoi.h) and
    // stops at the hull edge on the other end, whose far site b has no triangle after it.
    for (int t = first; t >= 0;) {
      const auto& tri = dv.triangles[t];
      const int corner = corner_of_site(dv, t, s);
      const int a = tri[(corner + 1) % 3];
      fan.emplace_back(squared_distance(s, a), a);
      const int next = dv.neighbors[t][(corner + 1) % 3];
      if (next == kInfinite) {
        const int b = tri[(corner + 2) % 3];
        fan.emplace_back(squared_distance(s, b), b);
      }
      t = next == first ? kInfinite : next;
    }
    std::sort(fan.begin(), fan.end());
    for (const auto& [d2, site] : fan) lists.sites.push_back(site);
  }
  lists.begin.push_back(static_cast<int>(lists.sites.size()));
  return lists;
}

// Spec step 1: each edge from a site to its nearest neighbour, each once, shortest first;
// equal lengths by edge (the reference keeps CGAL's edge-iteration order there).
std::vector<Edge> seed_edges(const SortedNeighbors& neighbors, const SquaredDistance& squared_distance) {
  const int n = static_cast<int>(neighbors.begin.size()) - 1;
  auto nearest = [&](int s) { return neighbors.begin[s] < neighbors.begin[s + 1] ? neighbors.sites[neighbors.begin[s]] : -1; };
  std::vector<std::pair<double, Edge>> seeds;
  seeds.reserve(n);
  for (int u = 0; u < n; ++u) {
    const int v = nearest(u);
    if (v < 0 || (v < u && nearest(v) == u)) continue;  // mutual nearest neighbours: listed from v
    seeds.emplace_back(squared_distance(u, v), make_edge(u, v));
  }
  std::sort(seeds.begin(), seeds.end());
  std::vector<Edge> edges;
  edges.reserve(seeds.size());
  for (const auto& [d2, edge] : seeds) edges.push_back(edge);
  return edges;
}

// Below dimension 2 the sites are collinear (or fewer than 2): lexicographic order is their
// order along the line, and the reference's single chain runs through them in that order.
std::vector<Edge> path_along_line(const std::vector<Point2>& sites) {
  std::vector<int> order(sites.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::pair(sites[a].x, sites[a].y) < std::pair(sites[b].x, sites[b].y);
  });
  std::vector<Edge> edges;
  for (size_t k = 1; k < order.size(); ++k) edges.push_back(make_edge(order[k - 1], order[k]));
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace

std::vector<Edge> crawl_edges(const DelaunayVoronoi& dv) {
  if (dv.dimension < 2) return path_along_line(dv.sites);
  const int n = dv.site_count();
  const SquaredDistance squared_distance(dv.sites);
  const SortedNeighbors neighbors = sorted_delaunay_neighbors(dv, squared_distance);
  const std::vector<Edge> seeds = seed_edges(neighbors, squared_distance);

  std::vector<std::uint8_t> used(n, 0);
  std::vector<int> cursor(neighbors.begin.begin(), neighbors.begin.end() - 1);
  auto nearest_unused = [&](int s) {
    int& k = cursor[s];
    while (k < neighbors.begin[s + 1] && used[neighbors.sites[k]]) ++k;
    return k < neighbors.begin[s + 1] ? neighbors.sites[k] : -1;
  };
  // Ranked over all Delaunay neighbours, used or not (spec step 3b).
  auto second_nearest = [&](int s) {
    return neighbors.begin[s + 1] - neighbors.begin[s] >= 2 ? neighbors.sites[neighbors.begin[s] + 1] : -1;
  };

  std::vector<Edge> edges;
  edges.reserve(n);
  // Spec step 2: the seeds are consumed in order; running out of them ends the method (the
  // reference pops an empty queue there).
  for (const Edge& seed : seeds) {
    if (used[seed[0]] || used[seed[1]]) continue;
    // Which end is e1 matters only for the tie in step 3e; CGAL's edge orientation decides it
    // in the reference, the smaller site index here.
    int end1 = seed[0], end2 = seed[1];
    edges.push_back(seed);
    used[end1] = used[end2] = 1;
    for (int steps = 0;;) {
      // Steps 3b and 3d close the same edge, so one test covers both. After 4 steps the chain
      // has 6 sites, so its two ends are never already joined.
      if (steps > 3 && (second_nearest(end1) == end2 || second_nearest(end2) == end1)) {
        edges.push_back(make_edge(end1, end2));
        break;
      }
      const int next1 = nearest_unused(end1), next2 = nearest_unused(end2);
      // Step 3e, with "no candidate" as an explicit case rather than the reference's 9999.
      if (next1 >= 0 && (next2 < 0 || squared_distance(end1, next1) < squared_distance(end2, next2))) {
        edges.push_back(make_edge(end1, next1));
        used[next1] = 1;
        end1 = next1;
      } else if (next2 >= 0) {
        edges.push_back(make_edge(end2, next2));
        used[next2] = 1;
        end2 = next2;
      } else {
        break;  // an open component
      }
      ++steps;
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench
