#include "labeling-holes/split_curves_joined_across_a_corridor.h"

#include "labeling-holes/curve_edges_per_sample.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {
namespace {

bool is_inner(const std::vector<std::uint8_t>& inner, int t) { return t != kInfinite && inner[t] != 0; }

}  // namespace

int split_curves_joined_across_a_corridor(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                          std::span<const int> seeds) {
  // Per triangle: the seed of the corridor grown through it (taken or not), so each is grown
  // once; -1 for none yet.
  std::vector<int> grown(dv.triangle_count(), -1);
  std::vector<int> corridor, stack, touched;
  std::vector<Edge> removed, added;
  std::vector<int> change(dv.site_count(), 0);  // per sample: curve edges gained minus lost
  std::vector<int> touched_by(dv.site_count(), -1);  // per sample: the seed of the last corridor on it
  int relabelled = 0;
  for (int seed : seeds) {
    if (!inner[seed] || grown[seed] >= 0) continue;
    bool starts = false;  // a curve edge that fails the crust test
    for (int k = 0; k < 3 && !starts; ++k) {
      starts = !is_inner(inner, dv.neighbors[seed][k]) && !is_one_step_crust_edge(dv, seed, k);
    }
    if (!starts) continue;
    // The corridor: inner triangles joined across edges that fail the crust test.
    corridor.clear();
    removed.clear();
    added.clear();
    grown[seed] = seed;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      corridor.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int next = dv.neighbors[t][k];
        if (next != kInfinite && grown[next] == seed) continue;  // in this corridor
        const Edge e{dv.triangles[t][(k + 1) % 3], dv.triangles[t][(k + 2) % 3]};
        if (!is_inner(inner, next)) {
          removed.push_back(e);
        } else if (is_one_step_crust_edge(dv, t, k)) {
          added.push_back(e);
        } else {  // not crust, so never an edge of a corridor grown before
          grown[next] = seed;
          stack.push_back(next);
        }
      }
    }
    if (added.empty()) continue;
    // Every sample of the corridor must then have exactly two curve edges.
    touched.clear();
    for (int t : corridor) {
      for (int site : dv.triangles[t]) {
        if (touched_by[site] != seed) touched.push_back(site);
        touched_by[site] = seed;
      }
    }
    for (const Edge& e : removed) {
      for (int site : e) {
        if (touched_by[site] != seed) touched.push_back(site);
        touched_by[site] = seed;
        --change[site];
      }
    }
    for (const Edge& e : added) {
      for (int site : e) {
        if (touched_by[site] != seed) touched.push_back(site);
        touched_by[site] = seed;
        ++change[site];
      }
    }
    bool manifold = true;
    for (int site : touched) {
      manifold = manifold && curve_edges_at(dv, inner, site) + change[site] == 2;
    }
    if (manifold) {
      for (int t : corridor) inner[t] = 0;
      relabelled += static_cast<int>(corridor.size());
    }
    for (int site : touched) change[site] = 0;
  }
  return relabelled;
}

}  // namespace curvebench
