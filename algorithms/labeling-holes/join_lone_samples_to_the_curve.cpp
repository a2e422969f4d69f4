#include "labeling-holes/join_lone_samples_to_the_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace curvebench {

std::optional<std::vector<int>> join_lone_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                  std::vector<int> lone) {
  auto label = [&](int t) { return t != kInfinite && inner[t] != 0; };
  auto distance = [&](int a, int b) { return std::sqrt(squared_distance(dv.sites[a], dv.sites[b])); };

  auto is_lone = [&](int site) { return std::binary_search(lone.begin(), lone.end(), site); };
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
      const bool on_the_curve = label(t) != label(dv.neighbors[t][corner]);  // the edge a-b
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

  // One round over the lone samples in index order; with `past_lone_neighbours`, a sample's
  // nearest neighbour is taken among the samples that are not lone, and the round stops at
  // the first join. True when it joined one.
  std::vector<int> joined;
  auto round = [&](bool past_lone_neighbours) {
    std::vector<int> left;
    bool progress = false;
    for (int s : lone) {
      const int t = (progress && past_lone_neighbours) ? kInfinite : joining_triangle(s, past_lone_neighbours);
      if (t == kInfinite) {
        left.push_back(s);
        continue;
      }
      inner[t] ^= 1;
      joined.push_back(t);
      progress = true;
    }
    lone.swap(left);
    return progress;
  };
  // A round past lone neighbours only when a strict one joined none: a tip cut off with two or
  // more samples, each the other's nearest neighbour (see the header).
  for (bool progress = true; progress && !lone.empty();) progress = round(false) || round(true);
  if (lone.empty()) return joined;
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
