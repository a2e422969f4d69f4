#include "labeling-holes/join_lone_samples_to_the_curve.h"

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "labeling-holes/curve_edges_per_sample.h"

namespace curvebench {

std::optional<std::vector<int>> join_lone_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                  std::vector<int> lone) {
  auto distance = [&](int a, int b) { return std::sqrt(squared_distance(dv.sites[a], dv.sites[b])); };

  std::set<int> remaining(lone.begin(), lone.end());
  auto is_lone = [&](int site) { return remaining.count(site) != 0; };
  // The triangle joining `s` to the curve, or kInfinite if none: counter-clockwise around s
  // from site_triangle, which for a hull site is the first of its open fan.
  auto joining_triangle = [&](int s, bool past_lone_neighbours) {
    int nearest = -1;
    double nearest_squared = std::numeric_limits<double>::infinity();
    const int first = dv.site_triangle[s];
    int t = first;
    do {
      for (int other : dv.triangles[t]) {
        const double d = squared_distance(dv.sites[s], dv.sites[other]);
        if (other == s || (past_lone_neighbours && is_lone(other))) continue;
        if (d < nearest_squared || (d == nearest_squared && other < nearest)) {
          nearest = other;
          nearest_squared = d;
        }
      }
      t = dv.neighbors[t][(corner_of_site(dv, t, s) + 1) % 3];
    } while (t != kInfinite && t != first);

    int best = kInfinite;
    double best_detour = std::numeric_limits<double>::infinity();
    t = first;
    do {
      const int corner = corner_of_site(dv, t, s);
      const int a = dv.triangles[t][(corner + 1) % 3], b = dv.triangles[t][(corner + 2) % 3];
      const bool on_the_curve = is_inner(inner, t) != is_inner(inner, dv.neighbors[t][corner]);  // the edge a-b
      if (on_the_curve && (a == nearest || b == nearest)) {
        const double detour = distance(s, a) + distance(s, b) - distance(a, b);
        if (detour < best_detour || (detour == best_detour && t < best)) {
          best = t;
          best_detour = detour;
        }
      }
      t = dv.neighbors[t][(corner + 1) % 3];
    } while (t != kInfinite && t != first);
    return best;
  };

  // Rounds over the lone samples in index order, a round past lone neighbours (stopping at its
  // first join) only when a strict one joined none: a tip cut off with two or more samples,
  // each the other's nearest neighbour (see the header). A sample is tested again only when a
  // join may have changed its answer: a join through triangle t relabels t's three edges and
  // makes its sample no longer lone, which concerns the lone neighbours of that sample and the
  // corners across t's edges. The rest would fail as they did, so each round and each round
  // past lone neighbours tests only those, in the same order: linear, not quadratic, on a tip
  // of many samples joined one by one (1e5 samples on a line and one off it).
  std::vector<int> joined;
  std::set<int> this_round(remaining.begin(), remaining.end()), next_round, past_lone(this_round);
  int cursor = -1;  // the sample this round tested last
  auto touch = [&](int site) {
    if (!is_lone(site)) return;
    past_lone.insert(site);
    (site > cursor ? this_round : next_round).insert(site);
  };
  auto join = [&](int s, int t) {
    inner[t] ^= 1;
    joined.push_back(t);
    remaining.erase(s);
    const int first = dv.site_triangle[s];
    int u = first;
    do {
      for (int corner : dv.triangles[u]) touch(corner);
      u = dv.neighbors[u][(corner_of_site(dv, u, s) + 1) % 3];
    } while (u != kInfinite && u != first);
    for (int across : dv.neighbors[t]) {
      if (across == kInfinite) continue;
      for (int corner : dv.triangles[across]) touch(corner);
    }
  };
  bool round_joined = false;
  while (!remaining.empty()) {
    if (!this_round.empty()) {
      const int s = *this_round.begin();
      this_round.erase(this_round.begin());
      cursor = s;
      const int t = is_lone(s) ? joining_triangle(s, false) : kInfinite;
      if (t != kInfinite) {
        join(s, t);
        round_joined = true;
      }
      continue;
    }
    if (round_joined && !next_round.empty()) {  // the next round
      this_round.swap(next_round);
      cursor = -1;
      round_joined = false;
      continue;
    }
    // A round that joined none: one past lone neighbours, then strict rounds again.
    int t = kInfinite, s = -1;
    while (t == kInfinite && !past_lone.empty()) {
      s = *past_lone.begin();
      past_lone.erase(past_lone.begin());
      if (is_lone(s)) t = joining_triangle(s, true);
    }
    if (t == kInfinite) break;
    cursor = -1;
    join(s, t);
    this_round.merge(next_round);
    next_round.clear();
    round_joined = false;
  }
  if (remaining.empty()) return joined;
  for (auto it = joined.rbegin(); it != joined.rend(); ++it) inner[*it] ^= 1;
  return std::nullopt;
}

int join_lone_samples_to_the_curve(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                   const std::vector<int>& curve_edges) {
  std::vector<int> lone;
  for (int s = 0; s < dv.site_count(); ++s) {
    if (dv.site_triangle[s] < 0) continue;  // a duplicate: its twin holds the cell
    if (curve_edges[s] == 0) {
      lone.push_back(s);
    } else if (curve_edges[s] != 2) {
      return 0;
    }
  }
  if (lone.empty()) return 0;
  const std::optional<std::vector<int>> joined = join_lone_samples(dv, inner, std::move(lone));
  return joined ? static_cast<int>(joined->size()) : 0;
}

}  // namespace curvebench
