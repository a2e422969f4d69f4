#include "hnn-crust/hnn_crust_edges.h"

#include <algorithm>
#include <cmath>

#include "core/nearest_neighbors.h"
#include "core/z_order.h"

namespace curvebench {
namespace {

// Neighbours asked for first. Most samples of a curve accept the rank-2 candidate, so a short
// query usually settles the half-neighbour; only the others pay for the full k_max query.
// Ranks by (distance, index) form one fixed order, so the short list is a prefix of the long
// one and the result is the same as querying k_max at once.
constexpr int kFirstQuery = 4;

// Sites are scaled so that the largest coordinate magnitude lies in [2^(kScale-1), 2^kScale).
// Squared distances then stay below 2^1006 (no overflow, which raw coordinates beyond ~1e154
// would cause), and distinct sites keep a nonzero squared distance down to separations of
// about 2^-1000 times the largest coordinate (raw tiny coordinates would underflow).
constexpr int kScale = 501;

// The sites times one power of two. Scaling up is exact; scaling down (only when the largest
// coordinate exceeds 2^501) is exact for every coordinate above 2^-499. Every distance
// comparison is then the one on the input.
std::vector<Point2> scaled_sites(std::span<const Point2> sites) {
  double largest = 0.0;
  for (const Point2& p : sites) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  int exponent = 0;
  std::frexp(largest, &exponent);
  const int shift = kScale - exponent;
  std::vector<Point2> scaled(sites.size());
  std::transform(sites.begin(), sites.end(), scaled.begin(), [&](Point2 p) {
    return Point2{std::ldexp(p.x, shift), std::ldexp(p.y, shift)};
  });
  return scaled;
}

// `ranked` (the query's k nearest sites) without the query site itself: ranks 1, 2, ... of
// spec step 1. Distinct sites put it at rank 0; should a squared distance still underflow to
// 0 (sites far closer than 2^-1000 times the largest coordinate), it may sit elsewhere or be
// missing, and then the list is cut to the same length anyway.
void drop_query_site(int site, std::vector<int>& ranked) {
  const auto at = std::find(ranked.begin(), ranked.end(), site);
  if (at != ranked.end()) {
    ranked.erase(at);
  } else if (!ranked.empty()) {
    ranked.pop_back();
  }
}

}  // namespace

std::vector<Edge> hnn_crust_edges(std::span<const Point2> sites, int k_max) {
  const int n = static_cast<int>(sites.size());
  if (n < 2) return {};  // spec section 3: n <= 1 gives no edges
  const std::vector<Point2> points = scaled_sites(sites);
  const NearestNeighbors neighbors(points);
  // Spec step 1: k = min(k_max, n), the site itself included. k_max below 2 would leave no
  // neighbour at all; the skeleton never passes it, and it is treated as 2.
  const int k = std::min(std::max(k_max, 2), n);

  std::vector<int> nearest(n, -1), half(n, -1);
  std::vector<int> ranked;
  for (const int p : z_order(points)) {
    const Point2 at = points[p];
    int asked = std::min(kFirstQuery, k);
    std::size_t next_candidate = 1;  // index into `ranked`; ranked[0] is a(p)
    while (true) {
      neighbors.k_nearest(at, asked, ranked);
      drop_query_site(p, ranked);
      if (ranked.empty()) break;
      nearest[p] = ranked[0];  // spec step 2
      const Point2 a = points[ranked[0]];
      // Spec step 3. The reference also asks |a - q| > |p - a|; it follows from this test,
      // since ranking gives |p - q| >= |p - a| (and the squared distances here are computed
      // exactly as the ranking computed them). Strict: a candidate on the bisector fails.
      for (; next_candidate < ranked.size(); ++next_candidate) {
        const Point2 q = points[ranked[next_candidate]];
        if (squared_distance(a, q) > squared_distance(at, q)) {
          half[p] = ranked[next_candidate];
          break;
        }
      }
      if (half[p] >= 0 || asked == k) break;
      asked = k;  // widen once to the full neighbourhood; ranks seen so far are not re-tested
    }
  }

  // Spec step 5: keep {p, c} only if c also chooses p. Emitted from the smaller end, each
  // site's (at most two) edges in order, so that the whole list comes out sorted.
  auto chooses = [&](int from, int to) { return nearest[from] == to || half[from] == to; };
  std::vector<Edge> edges;
  edges.reserve(n);
  for (int p = 0; p < n; ++p) {
    const int first = std::min(nearest[p], half[p]), second = std::max(nearest[p], half[p]);
    for (const int c : {first, second}) {
      if (c > p && chooses(c, p)) edges.push_back({p, c});
    }
  }
  return edges;
}

}  // namespace curvebench
