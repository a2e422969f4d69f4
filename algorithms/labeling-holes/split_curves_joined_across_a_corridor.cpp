#include "labeling-holes/split_curves_joined_across_a_corridor.h"

#include <algorithm>
#include <cmath>

#include "labeling-holes/curve_edges_per_sample.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {
namespace {

// Whether the angle at corner k of triangle t is at least 45 degrees, with a margin for
// rounding (a superset: the crust test decides). A curve edge that fails the crust test has
// angles at the two opposite corners summing to 90 degrees or more, so one of them is at
// least 45.
bool angle_at_least_45_degrees(const DelaunayVoronoi& dv, int t, int k) {
  const Point2 r = dv.sites[dv.triangles[t][k]];
  const Point2 u = dv.sites[dv.triangles[t][(k + 1) % 3]] - r, w = dv.sites[dv.triangles[t][(k + 2) % 3]] - r;
  return dot(u, w) <= 1.01 * std::abs(cross(u, w));  // cot(angle) <= 1
}

}  // namespace

std::vector<int> split_curves_joined_across_a_corridor(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                       std::uint8_t side) {
  auto label = [&](int t) { return t == kInfinite ? 0 : inner[t]; };  // the infinite vertex is outer
  std::vector<int> seeds;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int next = dv.neighbors[t][k];
      if (inner[t] == label(next) || !angle_at_least_45_degrees(dv, t, k)) continue;
      const int seed = inner[t] == side ? t : next;  // the curve edge's triangle on `side`
      if (seed != kInfinite) seeds.push_back(seed);
    }
  }
  if (seeds.empty()) return {};
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return split_curves_joined_across_a_corridor(dv, inner, seeds, side);
}

std::vector<int> split_curves_joined_across_a_corridor(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                       std::span<const int> seeds, std::uint8_t side) {
  auto label = [&](int t) { return t == kInfinite ? 0 : inner[t]; };  // the infinite vertex is outer
  // Per triangle: grown into no corridor yet, into the one growing, or into one before (taken
  // or not), so that each is grown once.
  enum : std::uint8_t { kNotGrown, kGrowing, kGrown };
  std::vector<std::uint8_t> grown(dv.triangle_count(), kNotGrown);
  std::vector<int> corridor, stack, touched;
  std::vector<Edge> removed, added;
  std::vector<int> change(dv.site_count(), 0);  // per sample: curve edges gained minus lost
  // Per sample: its curve edges, counted once (a fan walk) and then kept up to date, or -1 until
  // a corridor needs it.
  std::vector<int> count(dv.site_count(), -1);
  std::vector<std::uint8_t> touched_now(dv.site_count(), 0);  // per sample: on the corridor growing
  std::vector<int> relabelled;
  for (int seed : seeds) {
    if (inner[seed] != side || grown[seed] != kNotGrown) continue;
    bool starts = false;  // a curve edge that fails the crust test
    for (int k = 0; k < 3 && !starts; ++k) {
      starts = label(dv.neighbors[seed][k]) != side && !is_one_step_crust_edge(dv, seed, k);
    }
    if (!starts) continue;
    // The corridor: triangles of `side` joined across edges that fail the crust test.
    corridor.clear();
    removed.clear();
    added.clear();
    grown[seed] = kGrowing;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      corridor.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int next = dv.neighbors[t][k];
        if (next != kInfinite && grown[next] == kGrowing) continue;  // in this corridor
        const Edge e{dv.triangles[t][(k + 1) % 3], dv.triangles[t][(k + 2) % 3]};
        if (label(next) != side) {
          removed.push_back(e);
        } else if (next == kInfinite || is_one_step_crust_edge(dv, t, k)) {  // a hull edge: on the curve once relabelled
          added.push_back(e);
        } else {  // not crust, so never an edge of a corridor grown before
          grown[next] = kGrowing;
          stack.push_back(next);
        }
      }
    }
    for (int t : corridor) grown[t] = kGrown;
    if (added.empty()) continue;
    // Every sample of the corridor must then have exactly two curve edges.
    touched.clear();
    for (int t : corridor) {
      for (int site : dv.triangles[t]) {
        if (!touched_now[site]) touched.push_back(site);
        touched_now[site] = 1;
      }
    }
    for (const Edge& e : removed) {  // edges of the corridor's triangles: their ends are touched
      --change[e[0]];
      --change[e[1]];
    }
    for (const Edge& e : added) {
      ++change[e[0]];
      ++change[e[1]];
    }
    // Counted up to the first sample the corridor would leave with other than two curve edges,
    // which refuses it. A count not taken here is taken when a later corridor needs it, from the
    // labels as they are then, and equals the count kept up to date. (From a rejected curve edge
    // the corridor can be the whole interior, touching nearly every sample; its first refuse it.)
    const bool manifold = std::all_of(touched.begin(), touched.end(), [&](int site) {
      if (count[site] < 0) count[site] = curve_edges_at(dv, inner, site);
      return count[site] + change[site] == 2;
    });
    if (manifold) {
      for (int t : corridor) inner[t] = 1 - side;
      for (int site : touched) count[site] += change[site];
      relabelled.insert(relabelled.end(), corridor.begin(), corridor.end());
    }
    for (int site : touched) change[site] = touched_now[site] = 0;
  }
  return relabelled;
}

}  // namespace curvebench
